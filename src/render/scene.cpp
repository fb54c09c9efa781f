#include "render/scene.h"

namespace maxillo::render {

Bounds scene_bounds(const Scene& scene) {
  Bounds bounds;
  for (const auto& item : scene.meshes) {
    if (!item.mesh || item.mesh->vertex_count() == 0) continue;
    bounds.min = bounds.min.cwiseMin(item.mesh->vertices.colwise().minCoeff().transpose());
    bounds.max = bounds.max.cwiseMax(item.mesh->vertices.colwise().maxCoeff().transpose());
  }
  return bounds;
}

}  // namespace maxillo::render
