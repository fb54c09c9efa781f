#include "softtissue/bone_attachment.h"

#include <cmath>
#include <limits>

namespace maxillo::softtissue {
namespace {

// The segment label of the nearest bone voxel within `reach` mm of p, or 0.
uint8_t nearest_segment(const LabelVolume& segments, const Eigen::Vector3d& p, double reach) {
  const auto& g = segments.geometry;
  const Eigen::Vector3d centre = g.continuous_index(p);
  const Eigen::Vector3i radius = (Eigen::Vector3d::Constant(reach).cwiseQuotient(g.spacing)).array().ceil().cast<int>();
  const Eigen::Vector3i lo = (centre.array().floor().cast<int>() - radius.array()).matrix();
  const Eigen::Vector3i hi = (centre.array().ceil().cast<int>() + radius.array()).matrix();
  double best = reach * reach;
  uint8_t found = 0;
  for (int k = lo.z(); k <= hi.z(); ++k)
    for (int j = lo.y(); j <= hi.y(); ++j)
      for (int i = lo.x(); i <= hi.x(); ++i) {
        if (!g.contains(i, j, k)) continue;
        const uint8_t s = segments.labels[size_t(g.index(i, j, k))];
        if (!s) continue;
        const double d2 = (g.world(Eigen::Vector3d(i, j, k)) - p).squaredNorm();
        if (d2 <= best) {
          best = d2;
          found = s;
        }
      }
  return found;
}

bool on_cut(const Eigen::Vector3d& p, const std::vector<RegionPlane>& planes, double tolerance) {
  for (const auto& plane : planes)
    if (std::abs(plane.side(p)) <= tolerance) return true;
  return false;
}

}  // namespace

Attachment attach_to_bone(const TetMesh& mesh, const LabelVolume& segments,
                          const std::map<uint8_t, Eigen::Isometry3d>& moves, const std::vector<RegionPlane>& cut_planes,
                          const AttachmentOptions& options) {
  const int n = mesh.node_count();
  Attachment result;
  result.bc = all_free(n);
  result.segment.assign(size_t(n), 0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    const uint8_t s = nearest_segment(segments, p, options.touch_mm);
    result.segment[size_t(i)] = s;
    if (s) {
      auto move = moves.find(s);
      if (move != moves.end()) {
        result.bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
        result.bc.displacement.row(i) = (move->second * p - p).transpose();
      } else {
        result.bc.constraint[size_t(i)] = NodeConstraint::kFixed;
      }
    } else if (on_cut(p, cut_planes, options.cut_plane_tolerance_mm)) {
      result.bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    }
  }
  return result;
}

}  // namespace maxillo::softtissue
