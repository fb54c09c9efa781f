#include "casework/softtissue/exposed_bone.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geometry/vertex_normals.h"

namespace maxillo::casework {
namespace {

constexpr double kThinTissueMm = 2;  // tissue this thin over bone moves with it
constexpr double kDepthStepMm = 0.25;

}  // namespace

std::vector<uint8_t> exposed_bone_segments(const TriangleMesh& skin, const LabelVolume& segments) {
  const auto& g = segments.geometry;
  const VertexMatrix normals = vertex_normals(skin);
  std::vector<uint8_t> segment_of(size_t(skin.vertices.rows()), 0);
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v)
    for (double depth = kDepthStepMm; depth <= kThinTissueMm + 1e-9 && !segment_of[size_t(v)]; depth += kDepthStepMm) {
      const Eigen::Vector3d under = skin.vertices.row(v).transpose() - depth * normals.row(v).transpose();
      const Eigen::Vector3d ijk = g.continuous_index(under);
      const int i = int(std::lround(ijk.x())), j = int(std::lround(ijk.y())), k = int(std::lround(ijk.z()));
      if (g.contains(i, j, k)) segment_of[size_t(v)] = segments.labels[size_t(g.index(i, j, k))];
    }
  return segment_of;
}

void move_exposed_bone(const TriangleMesh& skin, const std::vector<uint8_t>& segment_of_vertex,
                       const SegmentMoves& moves, Eigen::MatrixX3d& displacement) {
  if (segment_of_vertex.size() != size_t(skin.vertices.rows()) || displacement.rows() != skin.vertices.rows())
    throw Error(ErrorCode::kProcessing, "skin on exposed bone", "the skin is not the one its segments were read for");
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v) {
    const uint8_t segment = segment_of_vertex[size_t(v)];
    if (!segment) continue;
    const auto move = moves.find(segment);
    const Eigen::Vector3d p = skin.vertices.row(v).transpose();
    const Eigen::Vector3d moved = move == moves.end() ? p : Eigen::Vector3d(move->second * p);
    displacement.row(v) = (moved - p).transpose();
  }
}

}  // namespace maxillo::casework
