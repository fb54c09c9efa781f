#include "softtissue/bone_attachment.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/topology_helpers.h"

namespace maxillo::softtissue {
namespace {

// Calls visit(label, centre, squared distance) for every bone voxel (non-zero label) whose
// centre lies within `reach` mm of p.
template <typename Visit>
void for_each_bone_voxel_near(const LabelVolume& segments, const Eigen::Vector3d& p, double reach, Visit visit) {
  const auto& g = segments.geometry;
  const Eigen::Vector3d centre = g.continuous_index(p);
  const Eigen::Vector3i radius = (Eigen::Vector3d::Constant(reach).cwiseQuotient(g.spacing)).array().ceil().cast<int>();
  const Eigen::Vector3i lo = (centre.array().floor().cast<int>() - radius.array()).matrix();
  const Eigen::Vector3i hi = (centre.array().ceil().cast<int>() + radius.array()).matrix();
  for (int k = lo.z(); k <= hi.z(); ++k)
    for (int j = lo.y(); j <= hi.y(); ++j)
      for (int i = lo.x(); i <= hi.x(); ++i) {
        if (!g.contains(i, j, k)) continue;
        const uint8_t s = segments.labels[size_t(g.index(i, j, k))];
        if (!s) continue;
        const Eigen::Vector3d q = g.world(Eigen::Vector3d(i, j, k));
        const double d2 = (q - p).squaredNorm();
        if (d2 <= reach * reach) visit(s, q, d2);
      }
}

// The segment label of the nearest bone voxel within `reach` mm of p, or 0.
uint8_t nearest_segment(const LabelVolume& segments, const Eigen::Vector3d& p, double reach) {
  double best = reach * reach;
  uint8_t found = 0;
  for_each_bone_voxel_near(segments, p, reach, [&](uint8_t s, const Eigen::Vector3d&, double d2) {
    if (d2 <= best) {
      best = d2;
      found = s;
    }
  });
  return found;
}

// The direction away from the bone near p: from the centroid of the bone voxels within `reach`
// mm (steadier than the nearest voxel's direction on a staircase surface); zero without bone.
Eigen::Vector3d away_from_bone(const LabelVolume& segments, const Eigen::Vector3d& p, double reach) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for_each_bone_voxel_near(segments, p, reach, [&](uint8_t, const Eigen::Vector3d& q, double) {
    sum += q;
    ++count;
  });
  if (!count) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d away = p - sum / count;
  return away.norm() > 1e-9 ? away.normalized() : Eigen::Vector3d::Zero();
}

// Whether the ray from p along unit `direction` meets bone between `from_mm` and `to_mm`; a ray
// that leaves the scan meets none.
bool ray_meets_bone(const LabelVolume& segments, const Eigen::Vector3d& p, const Eigen::Vector3d& direction,
                    double from_mm, double to_mm) {
  const auto& g = segments.geometry;
  const double step = 0.5 * g.spacing.minCoeff();
  for (double t = from_mm; t <= to_mm; t += step) {
    const Eigen::Vector3d ijk = g.continuous_index(p + t * direction);
    const int i = int(std::lround(ijk.x())), j = int(std::lround(ijk.y())), k = int(std::lround(ijk.z()));
    if (!g.contains(i, j, k)) return false;
    if (segments.labels[size_t(g.index(i, j, k))]) return true;
  }
  return false;
}

// A piece of the mesh that no fixed or prescribed node anchors (the lining of a sinus, cut off
// from the face by the mesher, that only cavities or sliding contact held) would float with
// nothing to hold it, and its solve would have no answer: its nodes follow their bone after all.
// `loose_segment`: per node, the moved segment it touches but was left free by (in its cavity, or
// not carried by it; 0 = none).
void hold_floating_pieces(const TetMesh& mesh, const std::vector<uint8_t>& loose_segment,
                          const std::map<uint8_t, Eigen::Isometry3d>& moves, Attachment& result) {
  const int n = mesh.node_count();
  topology::UnionFind pieces(n);
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int a = 1; a < 4; ++a) pieces.unite(mesh.tets(t, 0), mesh.tets(t, a));
  std::vector<char> held(size_t(n), 0);
  for (int i = 0; i < n; ++i) {
    const NodeConstraint c = result.bc.constraint[size_t(i)];
    if (c == NodeConstraint::kFixed || c == NodeConstraint::kPrescribed) held[size_t(pieces.find(i))] = 1;
  }
  for (int i = 0; i < n; ++i) {
    if (held[size_t(pieces.find(i))]) continue;
    if (result.bc.constraint[size_t(i)] == NodeConstraint::kSliding) {
      result.bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;  // its displacement is the bone's move
      continue;
    }
    const uint8_t s = loose_segment[size_t(i)];
    if (!s) continue;
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    result.bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
    result.bc.displacement.row(i) = (moves.at(s) * p - p).transpose();
    result.segment[size_t(i)] = s;
  }
}

// How many nodes touching moved bone were left free, and why: inside its cavity (`in_cavity`) or
// not carried by it.
void count_loose_nodes(const std::vector<uint8_t>& loose_segment, const std::vector<uint8_t>& in_cavity,
                       Attachment& result) {
  result.inner_nodes = result.uncarried_nodes = 0;
  for (size_t i = 0; i < loose_segment.size(); ++i) {
    if (!loose_segment[i] || result.bc.constraint[i] != NodeConstraint::kFree) continue;
    ++(in_cavity[i] ? result.inner_nodes : result.uncarried_nodes);
  }
}

// Joins node i at p to the moved segment s: tied, or sliding on the bone's surface when asked
// for and the bone's outward direction is defined there.
void join_to_moved_bone(const LabelVolume& segments, int i, const Eigen::Vector3d& p, const Eigen::Isometry3d& move,
                        const AttachmentOptions& options, BoundaryConditions& bc) {
  const Eigen::Vector3d bone_move = move * p - p;
  const bool slides =
      options.moved_bone_contact == MovedBoneContact::kSliding ||
      (options.moved_bone_contact == MovedBoneContact::kSlidingInCavities && inside_bone_cavity(segments, p, options));
  if (slides) {
    const Eigen::Vector3d normal = away_from_bone(segments, p, options.touch_mm + 1);
    if (!normal.isZero()) {
      make_sliding(bc, i, normal, bone_move);
      return;
    }
  }
  bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
  bc.displacement.row(i) = bone_move.transpose();
}

}  // namespace

const char* contact_name(MovedBoneContact contact) {
  switch (contact) {
    case MovedBoneContact::kSliding: return "sliding";
    case MovedBoneContact::kSlidingInCavities: return "sliding-in-cavities";
    default: return "tied";
  }
}

constexpr MovedBoneContact kContacts[] = {MovedBoneContact::kTied, MovedBoneContact::kSliding,
                                          MovedBoneContact::kSlidingInCavities};

std::optional<MovedBoneContact> contact_named(std::string_view name) {
  for (auto contact : kContacts)
    if (name == contact_name(contact)) return contact;
  return std::nullopt;
}

std::vector<std::string> contact_names() {
  std::vector<std::string> names;
  for (auto contact : kContacts) names.emplace_back(contact_name(contact));
  return names;
}

bool inside_bone_cavity(const LabelVolume& segments, const Eigen::Vector3d& p, const AttachmentOptions& options) {
  const Eigen::Vector3d outward = away_from_bone(segments, p, options.touch_mm + 1);
  if (outward.isZero()) return false;
  // Four directions 30 degrees off the outward one, about two axes across it.
  const Eigen::Vector3d across = outward.unitOrthogonal(), across2 = outward.cross(across);
  const double tilt = std::tan(30 * M_PI / 180);
  const Eigen::Vector3d rays[] = {outward, (outward + tilt * across).normalized(),
                                  (outward - tilt * across).normalized(), (outward + tilt * across2).normalized(),
                                  (outward - tilt * across2).normalized()};
  // The rays start clear of the bone the node touches, so that they do not meet it again at once.
  const double clear = options.touch_mm + 1;
  int meeting = 0;
  for (const auto& ray : rays) meeting += ray_meets_bone(segments, p, ray, clear, options.cavity_reach_mm);
  return meeting >= 3;
}

Attachment attach_to_bone(const TetMesh& mesh, const LabelVolume& segments,
                          const std::map<uint8_t, Eigen::Isometry3d>& moves, const RegionShape& region,
                          const AttachmentOptions& options, const std::vector<uint8_t>& not_carried) {
  const int n = mesh.node_count();
  Attachment result;
  result.bc = all_free(n);
  result.segment.assign(size_t(n), 0);
  std::vector<uint8_t> loose_segment(size_t(n), 0), in_cavity(size_t(n), 0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    const uint8_t s = nearest_segment(segments, p, options.touch_mm);
    result.segment[size_t(i)] = s;
    if (s) {
      auto move = moves.find(s);
      const bool moved = move != moves.end();
      const bool carried = not_carried.empty() || !not_carried[size_t(i)];
      const bool cavity = moved && carried && options.outer_surface_only && inside_bone_cavity(segments, p, options);
      if (moved && (!carried || cavity)) {  // touching moved bone, left free
        loose_segment[size_t(i)] = s;
        in_cavity[size_t(i)] = cavity;
        result.segment[size_t(i)] = 0;
      } else if (moved) {
        join_to_moved_bone(segments, i, p, move->second, options, result.bc);
      } else {
        result.bc.constraint[size_t(i)] = NodeConstraint::kFixed;
      }
    } else if (region.on_cut(p, options.cut_plane_tolerance_mm)) {
      result.bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    }
  }
  const bool any_loose = std::any_of(loose_segment.begin(), loose_segment.end(), [](uint8_t s) { return s != 0; });
  if (any_loose || any_sliding(result.bc)) hold_floating_pieces(mesh, loose_segment, moves, result);
  count_loose_nodes(loose_segment, in_cavity, result);
  return result;
}

}  // namespace maxillo::softtissue
