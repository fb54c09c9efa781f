#pragma once
// The linear FEM static solve by a conjugate gradient that works on the stiffness blocks
// directly (thesis ch. 6, sec. 2.1): no sparse matrix of the free system is assembled, the
// product K_ff p runs block row by block row (3 x 3 blocks, threads over the rows), and the
// preconditioner is block Jacobi (the inverse of each free node's 3 x 3 diagonal block), which
// on tetrahedral elasticity needs fewer iterations than point Jacobi.
#include <vector>

#include "softtissue/boundary_conditions.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {

// Same contract as solve_linear_static: n x 3 displacement with the imposed values on
// constrained nodes; stops when |r| / |b| <= options.relative_tolerance.
StaticSolution solve_block_pcg(const StiffnessBlocks& stiffness, const BoundaryConditions& bc,
                               const KrylovOptions& options = {});

// The same conjugate gradient for any right-hand side: K_ff x = b on the nodes with
// is_free[i] != 0. Vectors are node-major (entries 3 i .. 3 i + 2 belong to node i, length
// 3 n); b's entries on constrained nodes are ignored and x is 0 there. Used by the non-linear
// FEM for its Newton steps, with the tangent stiffness in `stiffness`.
struct BlockPcgResult {
  Eigen::VectorXd x;
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0;  // |b - K_ff x| / |b| over the free nodes
};
BlockPcgResult solve_free_block_pcg(const StiffnessBlocks& stiffness, const std::vector<char>& is_free,
                                    const Eigen::VectorXd& b, double relative_tolerance, int max_iterations);

}  // namespace maxillo::softtissue
