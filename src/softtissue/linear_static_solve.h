#pragma once
// Linear FEM static solve (thesis ch. 6, sec. 2.1) with a preconditioned conjugate gradient
// on K_ff u_f = -K_fc u_c. K_ff is symmetric positive definite once every rigid motion is
// blocked by constrained nodes.
#include "softtissue/boundary_conditions.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {

// kBlockJacobi: the matrix-free block solver of block_pcg.h (the default, fastest here);
// kJacobi and kIncompleteCholesky: Eigen's conjugate gradient on the assembled K_ff.
enum class Preconditioner { kJacobi, kIncompleteCholesky, kBlockJacobi };
enum class SolveStatus { kConverged, kNotConverged, kFactorisationFailed };

struct KrylovOptions {
  Preconditioner preconditioner = Preconditioner::kBlockJacobi;
  double relative_tolerance = 1e-8;  // on |K_ff u_f - b| / |b|
  int max_iterations = 20000;
};

struct StaticSolution {
  Eigen::MatrixX3d displacement;  // n x 3, mm
  SolveStatus status = SolveStatus::kNotConverged;
  int iterations = 0;
  double relative_residual = 0;
};

StaticSolution solve_linear_static(const StiffnessBlocks& stiffness, const BoundaryConditions& bc,
                                   const KrylovOptions& options = {});

}  // namespace maxillo::softtissue
