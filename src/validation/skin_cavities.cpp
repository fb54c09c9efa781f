#include "validation/skin_cavities.h"

#include <algorithm>

#include "geometry/vertex_normals.h"
#include "geometry/signed_distance.h"

namespace maxillo::validation {

std::vector<bool> cavity_vertices(const TriangleMesh& skin, const std::vector<bool>& include,
                                  const CavityOptions& options) {
  const DistanceField field(skin);
  const VertexMatrix normals = vertex_normals(skin);
  std::vector<bool> cavity(size_t(skin.vertex_count()), false);
  for (Eigen::Index v = 0; v < skin.vertex_count(); ++v) {
    if ((!include.empty() && !include[size_t(v)]) || normals.row(v).norm() == 0) continue;
    const Eigen::Vector3d start = skin.vertices.row(v).transpose();
    const Eigen::Vector3d direction = normals.row(v).transpose();
    // Start clear of the vertex's own surface; then step by the distance to the nearest surface,
    // which no surface can lie within.
    for (double t = 2 * options.step_mm; t <= options.reach_mm;) {
      const auto d = field.signed_distance(start + t * direction, options.probe_radius_mm);
      if (d.found && d.distance < 0) {
        cavity[size_t(v)] = true;
        break;
      }
      t += d.found ? std::max(d.distance, options.step_mm) : options.probe_radius_mm;
    }
  }
  return cavity;
}

}  // namespace maxillo::validation
