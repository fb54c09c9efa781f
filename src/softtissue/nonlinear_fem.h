#pragma once
// Non-linear FEM (thesis ch. 6, sec. 2.1: the complete Green-Lagrange strain instead of its
// linearisation) with a hyperelastic law: compressible neo-Hookean (the default, see
// HyperelasticLaw) or St Venant-Kirchhoff, S = lambda tr(E) I + 2 mu E, E = (F^T F - I) / 2,
// first Piola stress P = F S. Unlike linear FEM it is frame-invariant: a
// large rigid rotation of the boundary gives no stress. Static equilibrium with prescribed
// displacements is found by Newton's method on the free dofs with a backtracking line search,
// the imposed displacements applied in adaptive load steps (each starts from the previous answer).
// Each Newton system is solved by the matrix-free block-Jacobi conjugate gradient of
// block_pcg.h on the tangent assembled as 3 x 3 node blocks (no sparse matrix, no triplets).
#include "softtissue/boundary_conditions.h"
#include "softtissue/linear_elasticity.h"
#include "softtissue/stiffness_blocks.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

// The strain energy: St Venant-Kirchhoff (above), or compressible neo-Hookean,
//   W = mu/2 (tr(F^T F) - 3) - mu ln J + lambda/2 (ln J)^2,  P = mu F + (lambda ln J - mu) F^-T,
// whose energy grows without bound as a tet is crushed (J -> 0), where St Venant-Kirchhoff
// softens and lets Newton run into inverted elements.
enum class HyperelasticLaw { kStVenantKirchhoff, kNeoHookean };

struct NewtonOptions {
  HyperelasticLaw law = HyperelasticLaw::kNeoHookean;
  // The imposed displacements are applied in this many equal steps at most. A step that turns a
  // tet inside out, or whose Newton iterations do not converge, is undone and halved (adaptive
  // load stepping); after two accepted steps in a row the step doubles again, up to the planned
  // one. A thin element between nodes moved by different bones needs steps shorter than itself.
  int load_steps = 4;
  double smallest_load_fraction = 1.0 / 4096;  // give up below this step
  int max_iterations_per_step = 30;
  double relative_tolerance = 1e-6;  // on the free-dof residual, against the first step's first residual
  // Conjugate gradient on each Newton system, relative to its right-hand side. Inexact Newton:
  // the loop checks the true residual, so a loose value costs no accuracy, only (at worst) a
  // Newton step. On the 105,000-tet cube 1e-2 needs the same 9 Newton steps as 1e-8 with a
  // quarter of the CG iterations (568 against 2303).
  double linear_tolerance = 1e-2;
};

struct NonlinearSolution {
  Eigen::MatrixX3d displacement;  // n x 3, mm
  bool converged = false;
  int newton_iterations = 0;     // over all load steps
  int load_steps = 0;            // accepted load steps
  int rejected_steps = 0;        // load steps undone and halved
  double load_reached = 0;       // fraction of the imposed displacements in equilibrium (1 when converged)
  int linear_iterations = 0;     // conjugate gradient iterations over all Newton steps
  double relative_residual = 0;  // at the end
};

// Internal nodal forces (n x 3, N) at displacement u, each tet's material scaled by its
// TetMesh::stiffness_of (as in the tangent and the solve).
Eigen::MatrixX3d internal_forces(const TetMesh& mesh, const Material& material, const Eigen::MatrixX3d& u,
                                 HyperelasticLaw law = HyperelasticLaw::kNeoHookean);

// Tangent stiffness d f / d u at displacement u, as 3 x 3 node blocks over all nodes. Block
// (a, b) of a tet, in closed form (F = I + grad u, S the SVK stress, g the shape gradients):
//   V [ (g_a . S g_b) I + lambda F g_a (F g_b)^T + mu F g_b (F g_a)^T + mu (g_a . g_b) F F^T ],
// which at u = 0 is the linear element block of linear_elasticity.h.
// Neo-Hookean, with h_a = F^-T g_a: V [ mu (g_a . g_b) I + lambda h_a h_b^T + (mu - lambda ln J) h_b h_a^T ].
StiffnessBlocks tangent_stiffness(const TetMesh& mesh, const Material& material, const Eigen::MatrixX3d& u,
                                  HyperelasticLaw law = HyperelasticLaw::kNeoHookean);

NonlinearSolution solve_nonlinear_static(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
                                         const NewtonOptions& options = {});

}  // namespace maxillo::softtissue
