#include "validation/skin_cavities.h"

#include <algorithm>

#include "core/parallel_slabs.h"
#include "geometry/vertex_normals.h"
#include "geometry/signed_distance.h"

namespace maxillo::validation {

namespace {

// Whether the ray from `start` along `direction` enters the skin again within reach.
bool ray_reenters(const DistanceField& field, const Eigen::Vector3d& start, const Eigen::Vector3d& direction,
                  const CavityOptions& options) {
  // Start clear of the vertex's own surface; then step by the distance to the nearest surface,
  // which no surface can lie within.
  for (double t = 2 * options.step_mm; t <= options.reach_mm;) {
    const auto d = field.signed_distance(start + t * direction, options.probe_radius_mm);
    if (d.found && d.distance < 0) return true;
    t += d.found ? std::max(d.distance, options.step_mm) : options.probe_radius_mm;
  }
  return false;
}

}  // namespace

std::vector<bool> cavity_vertices(const TriangleMesh& skin, const std::vector<bool>& include,
                                  const CavityOptions& options) {
  const DistanceField field(skin);
  const VertexMatrix normals = vertex_normals(skin);
  // One byte per vertex while the rays run on the machine's cores: each vertex is its own slot
  // (neighbouring bits of a vector<bool> share a word, so threads must not write them).
  std::vector<char> lines_cavity(size_t(skin.vertex_count()), 0);
  for_each_slab(0, int(skin.vertex_count()), [&](int first, int last) {
    for (int v = first; v < last; ++v) {
      if ((!include.empty() && !include[size_t(v)]) || normals.row(v).norm() == 0) continue;
      lines_cavity[size_t(v)] =
          ray_reenters(field, skin.vertices.row(v).transpose(), normals.row(v).transpose(), options);
    }
  });
  return std::vector<bool>(lines_cavity.begin(), lines_cavity.end());
}

}  // namespace maxillo::validation
