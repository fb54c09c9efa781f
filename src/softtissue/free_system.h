#pragma once
// The static problem K u = 0 on free nodes with constrained displacements eliminated:
// K_ff u_f = -K_fc u_c, where f are free nodes and c fixed or prescribed ones. Sliding nodes
// (boundary_conditions.h) are not taken: number_free_nodes refuses them (Error), and
// block_pcg.h solves them.
// Free dof 3 f + c is free node number f (in node order) along axis c.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

#include "softtissue/boundary_conditions.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {

struct FreeNodeNumbering {
  std::vector<int> free_index;  // n; -1 for constrained nodes
  std::vector<int> free_nodes;  // node of each free number
  int free_count() const { return int(free_nodes.size()); }
};
FreeNodeNumbering number_free_nodes(const std::vector<NodeConstraint>& constraint);

// K_ff (3 nf x 3 nf, both triangles stored).
Eigen::SparseMatrix<double> free_free_matrix(const StiffnessBlocks& stiffness, const FreeNodeNumbering& numbering);
// -K_fc u_c (3 nf), the load the imposed displacements put on the free dofs.
Eigen::VectorXd free_load(const StiffnessBlocks& stiffness, const FreeNodeNumbering& numbering,
                          const BoundaryConditions& bc);
// Full n x 3 displacement: imposed values on constrained nodes, u_f on free ones.
Eigen::MatrixX3d assemble_displacement(const Eigen::VectorXd& free_solution, const FreeNodeNumbering& numbering,
                                       const BoundaryConditions& bc);
// max |f_i| over the free directions of f = K u (N): zero at equilibrium.
double max_free_force(const StiffnessBlocks& stiffness, const BoundaryConditions& bc, const Eigen::MatrixX3d& u);

}  // namespace maxillo::softtissue
