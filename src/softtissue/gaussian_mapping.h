#pragma once
// From the coarse tet mesh to the dense skin surface by distance-weighted interpolation
// (thesis ch. 6, eq. 14, the source's "Gaussian" scheme). Initialisation: each node Q_j on the
// tet mesh's outer surface is matched to its closest skin vertex P_j, which takes Q_j's
// displacement; every skin vertex P_i then averages the matched vertices P_j that lie within
// radius_mm of it and fewer than max_hops edges away on the skin, weighted by 1 / d_ij:
//   u(P_i) = sum_j u(P_j) / d_ij  /  sum_j 1 / d_ij.
// The source used 3 mm and connectivity below 5; the radius has to suit the tet mesh's node
// spacing (a skin vertex with no matched vertex within reach keeps a zero displacement).
// The weights are a sparse matrix, so an update is one sparse product.
#include <Eigen/SparseCore>
#include <vector>

#include "core/triangle_mesh.h"
#include "geometry/aabb_tree.h"
#include "softtissue/tet_boundary.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct GaussianMappingOptions {
  double radius_mm = 3.0;
  int max_hops = 4;                    // "connectivity lower than 5"
  double max_match_distance_mm = 5.0;  // a surface node farther from the skin is not matched
};

struct GaussianMapping {
  Eigen::SparseMatrix<double, Eigen::RowMajor> weights;  // skin vertices x mesh nodes, rows sum to 1 or 0
  int bound_count = 0;                                   // skin vertices with at least one weight
};

// What the skin offers to every mapping, built once per skin (the pre-operative skin does not
// change between plans): a closest-point tree and the vertex adjacency in compressed rows.
struct SkinIndex {
  explicit SkinIndex(const TriangleMesh& skin);
  const TriangleMesh* skin;
  AabbTree tree;
  std::vector<int> offsets, neighbours;
};

// The initialisation proper: matching the model's surface nodes to the skin and collecting the
// weights. `boundary` is tet_boundary(mesh), built once per model.
GaussianMapping init_gaussian_mapping(const TetMesh& mesh, const TetBoundary& boundary, const SkinIndex& skin,
                                      const GaussianMappingOptions& options = {});
// All in one: builds the boundary and the skin index first.
GaussianMapping init_gaussian_mapping(const TetMesh& mesh, const TriangleMesh& skin,
                                      const GaussianMappingOptions& options = {});

// Displacement of every skin vertex, mm.
Eigen::MatrixX3d map_displacement(const GaussianMapping& mapping, const Eigen::MatrixX3d& node_displacement);

}  // namespace maxillo::softtissue
