#include "softtissue/boundary_move.h"

#include <algorithm>

namespace maxillo::softtissue {

std::vector<double> largest_move_near_planes(const TetMesh& mesh, const Eigen::MatrixX3d& displacement,
                                             const std::vector<RegionPlane>& planes, double band_mm) {
  std::vector<double> largest(planes.size(), 0.0);
  for (int n = 0; n < mesh.node_count(); ++n) {
    const Eigen::Vector3d p = mesh.nodes.row(n).transpose();
    for (size_t k = 0; k < planes.size(); ++k) {
      const double depth = planes[k].side(p);
      if (depth >= -1e-9 && depth <= band_mm) largest[k] = std::max(largest[k], displacement.row(n).norm());
    }
  }
  return largest;
}

}  // namespace maxillo::softtissue
