#pragma once
// The global linear FEM stiffness of a tet mesh stored per node pair as 3 x 3 blocks on the
// node graph: block(i, j) = sum over tets containing i and j of the element blocks (N/mm).
// These are exactly the mass tensor model's K_jj (diagonal) and K_jk (thesis eq. 10); the
// force on node i is f_i = sum_j block(i, j) u_j (the elastic force is -f). Each tet's material
// is scaled by its TetMesh::stiffness_of.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

#include "softtissue/linear_elasticity.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct StiffnessBlocks {
  NodeGraph graph;                      // rows: nodes; neighbours include the node itself
  std::vector<Eigen::Matrix3d> blocks;  // one per graph entry, same order as graph.neighbours
  int node_count() const { return int(graph.offsets.size()) - 1; }
};

StiffnessBlocks assemble_stiffness_blocks(const TetMesh& mesh, const Material& material);

// K as a 3n x 3n sparse matrix, dof 3 i + c for node i and axis c.
Eigen::SparseMatrix<double> to_sparse_matrix(const StiffnessBlocks& stiffness);

// f = K u for displacements u (n x 3, mm); rows are node forces (N).
Eigen::MatrixX3d multiply(const StiffnessBlocks& stiffness, const Eigen::MatrixX3d& u);

}  // namespace maxillo::softtissue
