#pragma once
// Non-linear FEM (thesis ch. 6, sec. 2.1: the complete Green-Lagrange strain instead of its
// linearisation) with the St Venant-Kirchhoff material: S = lambda tr(E) I + 2 mu E,
// E = (F^T F - I) / 2, first Piola stress P = F S. Unlike linear FEM it is frame-invariant: a
// large rigid rotation of the boundary gives no stress. Static equilibrium with prescribed
// displacements is found by Newton's method on the free dofs with a backtracking line search,
// the imposed displacements applied in load steps (each step starts from the previous answer).
#include "softtissue/boundary_conditions.h"
#include "softtissue/linear_elasticity.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct NewtonOptions {
  int load_steps = 4;
  int max_iterations_per_step = 30;
  double relative_tolerance = 1e-6;  // on the free-dof residual, against the first step's first residual
  double linear_tolerance = 1e-8;    // conjugate gradient on each Newton system
};

struct NonlinearSolution {
  Eigen::MatrixX3d displacement;  // n x 3, mm
  bool converged = false;
  int newton_iterations = 0;      // over all load steps
  int linear_iterations = 0;      // conjugate gradient iterations over all Newton steps
  double relative_residual = 0;   // at the end
};

// Internal nodal forces (n x 3, N) of the SVK material at displacement u.
Eigen::MatrixX3d internal_forces(const TetMesh& mesh, const Material& material, const Eigen::MatrixX3d& u);

NonlinearSolution solve_nonlinear_static(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
                                         const NewtonOptions& options = {});

}  // namespace maxillo::softtissue
