#pragma once
// From the coarse tet mesh to the dense skin surface by the FEM shape functions (thesis ch. 6,
// eq. 13). Initialisation: a point inside the model is bound to the tet holding it; a point
// outside (the skin lies on or just off the model's surface) is projected on the tet mesh's
// outer surface and bound to the tet owning the triangle it lands on, as in the source. The
// weights are that tet's linear shape functions (barycentric coordinates) at the point, or for
// a point outside, at its projection (it moves with the model's surface point beneath it;
// extrapolating from a flat boundary tet could amplify the displacement many times).
// Update: u(P) = sum_j N_j(P) u_j over the tet's four nodes.
#include <Eigen/Core>
#include <vector>

#include "core/triangle_mesh.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct ShapeFunctionMapping {
  std::vector<int> tet;                  // per skin point; -1 = not bound (beyond max_distance)
  std::vector<Eigen::Vector4d> weights;  // N_0..N_3 at the point; they sum to 1
  int bound_count() const;
};

// Points farther than max_distance_mm from the tet mesh's surface stay unbound: they lie
// outside the modelled region and keep a zero displacement.
ShapeFunctionMapping init_shape_function_mapping(const TetMesh& mesh, const VertexMatrix& points,
                                                 double max_distance_mm);

// Displacement of every point (rows of the init's `points`), mm.
Eigen::MatrixX3d map_displacement(const TetMesh& mesh, const ShapeFunctionMapping& mapping,
                                  const Eigen::MatrixX3d& node_displacement);

// Barycentric coordinates of p in tet t (the linear shape functions at p).
Eigen::Vector4d shape_functions(const TetMesh& mesh, int t, const Eigen::Vector3d& p);

}  // namespace maxillo::softtissue
