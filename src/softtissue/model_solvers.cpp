#include "softtissue/model_solvers.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/error.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/mass_spring_model.h"
#include "softtissue/mass_tensor_model.h"
#include "softtissue/nonlinear_fem.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {
namespace {

using SetupClock = std::chrono::steady_clock;
double setup_seconds_since(SetupClock::time_point start) {
  return std::chrono::duration<double>(SetupClock::now() - start).count();
}

// The largest tet stiffness over the smallest (1 for one homogeneous tissue). The point-wise
// solvers' stop rule (a point at rest when its update moves it less than the threshold) is
// the thesis' for one tissue; a stiff region joined to soft tissue slows the sweeps about as
// much as the stiffness differs, and they stop far from rest: the cadaver's nose 68 times
// stiffer, the mass tensor model stopped at 1e-3 mm with the nose tip 0.24 mm behind the linear
// FEM's answer to the same equations; the threshold divided by the contrast reaches it.
double stiffness_contrast(const TetMesh& mesh) {
  if (mesh.stiffness.empty()) return 1;
  const auto [low, high] = std::minmax_element(mesh.stiffness.begin(), mesh.stiffness.end());
  return *high / *low;
}

LocalIterationOptions local_iteration_options(const TetMesh& mesh, const ModelSolveOptions& options) {
  LocalIterationOptions local;
  local.gradient_threshold_mm = options.gradient_threshold_mm / stiffness_contrast(mesh);
  local.max_iterations = options.max_sweeps;
  return local;
}

// The local iterations stop at their sweep limit with points still moving: that face is not
// the model's answer, so it is an error naming the model and how far from rest it was.
void require_at_rest(const LocalIterationResult& result, const LocalIterationOptions& options, const char* model) {
  if (result.status == IterationStatus::kConverged) return;
  throw Error(ErrorCode::kProcessing, model,
              "did not come to rest: after " + std::to_string(result.iterations) + " sweeps a point still moved " +
                  std::to_string(result.last_max_move_mm) + " mm per sweep (threshold " +
                  std::to_string(options.gradient_threshold_mm) + " mm)");
}

}  // namespace

ModelSolution solve_mass_tensor_model(const TetMesh& mesh, const BoundaryConditions& bc,
                                      const ModelSolveOptions& options) {
  const auto start = SetupClock::now();
  const auto local = local_iteration_options(mesh, options);
  const auto blocks = assemble_stiffness_blocks(mesh, options.material);
  const auto model = make_mass_tensor_model(blocks);
  const double assembly_seconds = setup_seconds_since(start);
  auto result = solve_mass_tensor(model, bc, local);
  require_at_rest(result, local, "mass tensor model");
  return {std::move(result.displacement), result.iterations, assembly_seconds};
}

ModelSolution solve_linear_fem(const TetMesh& mesh, const BoundaryConditions& bc, const ModelSolveOptions& options) {
  const auto start = SetupClock::now();
  const auto blocks = assemble_stiffness_blocks(mesh, options.material);
  const double assembly_seconds = setup_seconds_since(start);
  auto result = solve_linear_static(blocks, bc);
  if (result.status != SolveStatus::kConverged)
    throw Error(ErrorCode::kProcessing, "linear FEM", "the conjugate gradient did not converge");
  return {std::move(result.displacement), result.iterations, assembly_seconds};
}

ModelSolution solve_mass_spring_model(const TetMesh& mesh, const BoundaryConditions& bc,
                                      const ModelSolveOptions& options) {
  const auto start = SetupClock::now();
  const auto local = local_iteration_options(mesh, options);
  const auto model = make_van_gelder_model(mesh, options.material.young_modulus_mpa);
  const double assembly_seconds = setup_seconds_since(start);
  auto result = solve_mass_spring(model, bc, local);
  require_at_rest(result, local, "mass-spring model");
  return {std::move(result.displacement), result.iterations, assembly_seconds};
}

ModelSolution solve_nonlinear_fem(const TetMesh& mesh, const BoundaryConditions& bc, const ModelSolveOptions& options) {
  NewtonOptions newton;
  newton.load_steps = 2;
  auto result = solve_nonlinear_static(mesh, options.material, bc, newton);
  if (!result.converged)
    throw Error(ErrorCode::kProcessing, "non-linear FEM",
                "Newton's method did not converge: it stopped at " + std::to_string(int(100 * result.load_reached)) +
                    " %" + " of the bone's move, where a step of 1/" +
                    std::to_string(int(std::lround(1 / newton.smallest_load_fraction))) +
                    " of it still turned a tetrahedron inside out or did not converge (" +
                    std::to_string(result.load_steps) + " load steps, " + std::to_string(result.newton_iterations) +
                    " Newton steps)");
  return {std::move(result.displacement), result.newton_iterations, 0};  // the tangent is assembled in every step
}

}  // namespace maxillo::softtissue
