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

// The same conjugate gradient for any right-hand side: K_ff x = b in the free directions of
// `free_directions` (all three of a free node, the two across the normal of a sliding one, none
// of a fixed or prescribed one; its imposed values are not read). Vectors are node-major
// (entries 3 i .. 3 i + 2 belong to node i, length 3 n); b's parts in constrained directions are
// ignored and x has none. Used by the non-linear FEM for its Newton steps, with the tangent
// stiffness in `stiffness`. A b that is not finite returns at once: not converged, x = 0.
//
// With `stop_at_negative_curvature` (Newton on an energy whose tangent may be indefinite: a
// compressed tissue near buckling) the iteration stops where it meets a direction p with
// p^T K p <= 0 and returns the iterate so far, or the preconditioned right-hand side if that
// happens at once: either is a descent direction of the energy when b is minus its gradient
// (Steihaug's truncated conjugate gradient; Nocedal and Wright, Numerical Optimization, alg. 7.1).
struct BlockPcgResult {
  Eigen::VectorXd x;
  bool converged = false;
  bool negative_curvature = false;  // stopped at a direction of negative curvature
  int iterations = 0;
  double relative_residual = 0;  // |b - K_ff x| / |b| over the free nodes
};
BlockPcgResult solve_free_block_pcg(const StiffnessBlocks& stiffness, const BoundaryConditions& free_directions,
                                    const Eigen::VectorXd& b, double relative_tolerance, int max_iterations,
                                    bool stop_at_negative_curvature = false);

}  // namespace maxillo::softtissue
