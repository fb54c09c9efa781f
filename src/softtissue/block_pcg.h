#pragma once
// The linear FEM static solve by a conjugate gradient that works on the stiffness blocks
// directly (thesis ch. 6, sec. 2.1): no sparse matrix of the free system is assembled, the
// product K_ff p runs block row by block row (3 x 3 blocks, threads over the rows), and the
// preconditioner is block Jacobi (the inverse of each free node's 3 x 3 diagonal block), which
// on tetrahedral elasticity needs fewer iterations than point Jacobi.
#include "softtissue/boundary_conditions.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {

// Same contract as solve_linear_static: n x 3 displacement with the imposed values on
// constrained nodes; stops when |r| / |b| <= options.relative_tolerance.
StaticSolution solve_block_pcg(const StiffnessBlocks& stiffness, const BoundaryConditions& bc,
                               const KrylovOptions& options = {});

}  // namespace maxillo::softtissue
