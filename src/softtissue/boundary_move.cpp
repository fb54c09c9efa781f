#include "softtissue/boundary_move.h"

#include <algorithm>

namespace maxillo::softtissue {
namespace {

// A step this far beyond a plane tells a cut (outside the shape) from a meeting of two pieces.
constexpr double kStepBeyondMm = 1;

}  // namespace

std::vector<double> largest_move_near_planes(const TetMesh& mesh, const Eigen::MatrixX3d& displacement,
                                             const RegionShape& shape, double band_mm) {
  std::vector<double> largest;
  for (size_t k = 0; k < shape.pieces.size(); ++k)
    for (size_t q = 0; q < shape.pieces[k].size(); ++q) {
      double move = 0;
      for (int n = 0; n < mesh.node_count(); ++n) {
        const Eigen::Vector3d p = mesh.nodes.row(n).transpose();
        const double depth = shape.pieces[k][q].side(p);
        if (depth >= -1e-9 && depth <= band_mm && shape.cut_behind(p, k, q, kStepBeyondMm))
          move = std::max(move, displacement.row(n).norm());
      }
      largest.push_back(move);
    }
  return largest;
}

}  // namespace maxillo::softtissue
