#include "softtissue/shape_function_mapping.h"

#include <Eigen/LU>
#include <algorithm>

#include "geometry/aabb_tree.h"
#include "softtissue/tet_boundary.h"
#include "softtissue/tet_locator.h"

namespace maxillo::softtissue {

int ShapeFunctionMapping::bound_count() const {
  return int(std::count_if(tet.begin(), tet.end(), [](int t) { return t >= 0; }));
}

Eigen::Vector4d shape_functions(const TetMesh& mesh, int t, const Eigen::Vector3d& p) {
  const auto corners = tet_corners(mesh, t);
  Eigen::Matrix3d edges;
  for (int c = 0; c < 3; ++c) edges.col(c) = (corners.row(c + 1) - corners.row(0)).transpose();
  const Eigen::Vector3d local = edges.partialPivLu().solve(p - corners.row(0).transpose());
  return {1 - local.sum(), local.x(), local.y(), local.z()};
}

ShapeFunctionMapping init_shape_function_mapping(const TetMesh& mesh, const VertexMatrix& points,
                                                 double max_distance_mm) {
  const TetBoundary boundary = tet_boundary(mesh);
  const AabbTree tree(boundary.surface);
  const TetLocator locator(mesh);
  ShapeFunctionMapping mapping;
  mapping.tet.assign(size_t(points.rows()), -1);
  mapping.weights.assign(size_t(points.rows()), Eigen::Vector4d::Zero());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = points.row(i).transpose();
    int t = locator.find(p);  // inside the model: the tet holding the point
    Eigen::Vector4d weights;
    if (t >= 0) {
      weights = shape_functions(mesh, t, p);
    } else {  // outside: the tet under its projection on the outer surface
      const auto nearest = tree.nearest(p, max_distance_mm);
      if (nearest.face < 0) continue;
      t = boundary.tet_of_face[size_t(nearest.face)];
      // Evaluated at the projection, not extrapolated: linear extrapolation from a flat
      // boundary tet can amplify its nodes' displacements many times.
      weights = shape_functions(mesh, t, nearest.point).cwiseMax(0.0);
      weights /= weights.sum();
    }
    mapping.tet[size_t(i)] = t;
    mapping.weights[size_t(i)] = weights;
  }
  return mapping;
}

Eigen::MatrixX3d map_displacement(const TetMesh& mesh, const ShapeFunctionMapping& mapping,
                                  const Eigen::MatrixX3d& node_displacement) {
  Eigen::MatrixX3d result = Eigen::MatrixX3d::Zero(Eigen::Index(mapping.tet.size()), 3);
  for (size_t i = 0; i < mapping.tet.size(); ++i) {
    const int t = mapping.tet[i];
    if (t < 0) continue;
    for (int c = 0; c < 4; ++c)
      result.row(Eigen::Index(i)) += mapping.weights[i][c] * node_displacement.row(mesh.tets(t, c));
  }
  return result;
}

}  // namespace maxillo::softtissue
