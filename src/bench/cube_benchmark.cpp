#include "bench/cube_benchmark.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <vector>

#include "bench/formatted.h"
#include "bench/timing.h"
#include "core/error.h"
#include "core/temporary_folder.h"
#include "softtissue/blas_library.h"
#include "softtissue/calculix_deck.h"
#include "softtissue/cube_benchmark.h"
#include "softtissue/element_quality.h"
#include "softtissue/mass_spring_model.h"
#include "softtissue/mass_tensor_model.h"
#include "softtissue/nonlinear_fem.h"
#include "softtissue/rigid_plan_basis.h"
#include "softtissue/vtu_writer.h"

namespace maxillo::bench {
namespace {

using namespace maxillo::softtissue;

struct CubeProblem {
  CubeSpec spec;
  TetMesh mesh;
  BoundaryConditions bc;
  StiffnessBlocks stiffness;
  double assembly_seconds = 0;
};

CubeProblem make_cube_problem(const CubeBenchOptions& options) {
  CubeProblem cube;
  cube.spec = {100.0, cube_divisions_for_tets(options.tets, options.split), options.split};
  cube.mesh = make_cube_mesh(cube.spec);
  cube.bc = cube_benchmark_conditions(cube.mesh, cube.spec);
  cube.assembly_seconds = seconds_of([&] { cube.stiffness = assemble_stiffness_blocks(cube.mesh, Material{}); });
  return cube;
}

Eigen::VectorX<bool> free_mask(const BoundaryConditions& bc) {
  Eigen::VectorX<bool> mask(bc.node_count());
  for (int i = 0; i < bc.node_count(); ++i) mask(i) = bc.is_free(i);
  return mask;
}

Eigen::MatrixX3d converged_fem(const CubeProblem& cube) {
  StaticSolution reference = solve_linear_static(cube.stiffness, cube.bc, {Preconditioner::kJacobi, 1e-12, 100000});
  if (reference.status != SolveStatus::kConverged)
    throw Error(ErrorCode::kProcessing, "bench cube", "the reference FEM solve did not converge");
  return reference.displacement;
}

// Plan changes: the centre's lift varies, the constraint pattern stays. The median seconds of
// a re-solve with the factorisation made once.
double resolve_seconds(const CubeProblem& cube, const FactorisedElasticity& factorised, int runs) {
  std::vector<double> times;
  BoundaryConditions changed = cube.bc;
  Eigen::MatrixX3d displacement;
  for (int run = 0; run < std::max(runs, 3); ++run) {
    for (int i = 0; i < changed.node_count(); ++i)
      if (changed.constraint[size_t(i)] == NodeConstraint::kPrescribed) changed.displacement(i, 2) = 6.0 - 0.5 * run;
    times.push_back(seconds_of([&] { displacement = solve_factorised(factorised, changed); }));
  }
  return median(times);
}

// The rigid-plan fast path: the centre is one bone segment; a plan change is a new motion.
// Its figures, and how far its answer for the 6 mm lift lies from `displacement` (mm).
Json rigid_plan_figures(const CubeProblem& cube, const FactorisedElasticity& factorised, int runs,
                        const Eigen::MatrixX3d& displacement) {
  std::vector<int> segment(size_t(cube.mesh.node_count()), 0);
  RigidPlanBasis basis;
  const double basis_seconds =
      seconds_of([&] { basis = precompute_rigid_plan_basis(factorised, cube.mesh, cube.bc.constraint, segment, 1); });
  std::vector<double> plan_times;
  Eigen::MatrixX3d planned;
  for (int run = 0; run < std::max(runs, 3); ++run) {
    std::vector<Eigen::Isometry3d> motion(1, Eigen::Isometry3d::Identity());
    motion[0]
        .rotate(Eigen::AngleAxisd(0.05 * run, Eigen::Vector3d::UnitX()))
        .pretranslate(Eigen::Vector3d(0, 0, 6.0 - run));
    plan_times.push_back(seconds_of([&] { planned = solve_rigid_plan(basis, motion); }));
  }
  std::vector<Eigen::Isometry3d> lift(1, Eigen::Isometry3d::Identity());
  lift[0].pretranslate(Eigen::Vector3d(0, 0, 6.0));
  return {{"rigid_plan_basis_seconds", basis_seconds},
          {"rigid_plan_resolve_seconds", median(plan_times)},
          {"rigid_plan_vs_resolve_max_mm", (solve_rigid_plan(basis, lift) - displacement).cwiseAbs().maxCoeff()}};
}

// CalculiX's linear static step on the same cube: its wall seconds (reading the deck, assembling,
// its direct solver, writing the answer, as a user runs it), the largest difference between its
// answer and `fem`, and how many times faster the FEM's assembly and solve (`fem_seconds`) are.
Json calculix_figures(const CubeProblem& cube, const Eigen::MatrixX3d& fem, double fem_seconds) {
  if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    throw Error(ErrorCode::kUsage, "bench cube --calculix", "ccx not found (scripts/setup installs calculix-ccx)");
  TemporaryFolder folder("bench-calculix");
  std::ofstream(folder / "cube.inp") << calculix_deck(cube.mesh, Material{}, cube.bc);
  int status = 0;
  const double seconds = seconds_of(
      [&] { status = std::system(("cd '" + folder.path().string() + "' && ccx -i cube > ccx.log 2>&1").c_str()); });
  std::ifstream dat(folder / "cube.dat");
  const Eigen::MatrixX3d theirs = read_calculix_displacements(dat, cube.mesh.node_count());
  if (status != 0 || !theirs.allFinite())
    throw Error(ErrorCode::kProcessing, "bench cube --calculix",
                "ccx did not solve the cube (exit status " + std::to_string(status) + ")");
  return {{"calculix_seconds", seconds},
          {"calculix_vs_fem_worst_mm", (theirs - fem).cwiseAbs().maxCoeff()},
          {"fem_speedup_over_calculix", seconds / fem_seconds}};
}

Json bench_fem(const CubeProblem& cube, const CubeBenchOptions& options, Eigen::MatrixX3d& displacement) {
  StaticSolution solution;
  const double solve_seconds = median_seconds(options.runs, [&] {
    solution = solve_linear_static(cube.stiffness, cube.bc, {options.preconditioner, options.tolerance, 100000});
  });
  if (solution.status != SolveStatus::kConverged)
    throw Error(ErrorCode::kProcessing, "bench cube", "the conjugate gradient did not converge");
  Precision precision = precision_against(solution.displacement, converged_fem(cube), free_mask(cube.bc));
  FactorisedElasticity factorised;
  const double factorise_seconds = median_seconds(options.runs, [&] {
    if (precompute_factorisation(cube.stiffness, cube.bc.constraint, options.cholesky, factorised) !=
        FactorisationStatus::kOk)
      throw Error(ErrorCode::kProcessing, "bench cube", "the Cholesky factorisation failed or is not built in");
  });
  const double resolve = resolve_seconds(cube, factorised, options.runs);
  displacement = solve_factorised(factorised, cube.bc);
  Json figures = {{"solve_seconds", solve_seconds},
                  {"iterations", solution.iterations},
                  {"relative_residual", solution.relative_residual},
                  {"precision_worst_mm", precision.worst_mm},
                  {"precision_mean_mm", precision.mean_mm},
                  {"factorise_seconds", factorise_seconds},
                  {"factor_nonzeros", factorised.factor_nonzeros},
                  {"blas", blas_library()},
                  {"cholesky", factorised.backend == CholeskyBackend::kCholmodSupernodal ? "cholmod" : "eigen"},
                  {"resolve_seconds", resolve}};
  figures.update(rigid_plan_figures(cube, factorised, options.runs, displacement));
  if (options.calculix)
    figures.update(calculix_figures(cube, solution.displacement, cube.assembly_seconds + solve_seconds));
  return figures;
}

Json bench_mtm(const CubeProblem& cube, const CubeBenchOptions& options, Eigen::MatrixX3d& displacement) {
  MassTensorModel model;
  double precompute_seconds = seconds_of([&] { model = make_mass_tensor_model(cube.stiffness); });
  const Eigen::MatrixX3d converged = converged_fem(cube);
  auto table_row = [&](const LocalIterationOptions& local, int runs) {
    LocalIterationResult result;
    const double seconds = median_seconds(runs, [&] { result = solve_mass_tensor(model, cube.bc, local); });
    Precision precision = precision_against(result.displacement, converged, free_mask(cube.bc));
    return std::pair{Json{{"gradient_threshold_mm", local.gradient_threshold_mm},
                          {"relaxation", local.relaxation},
                          {"solve_seconds", seconds},
                          {"iterations", result.iterations},
                          {"point_updates", result.point_updates},
                          {"precision_worst_mm", precision.worst_mm},
                          {"precision_mean_mm", precision.mean_mm},
                          {"converged", result.status == IterationStatus::kConverged}},
                     result.displacement};
  };
  auto [main, main_displacement] = table_row(options.local, options.runs);
  displacement = main_displacement;
  Json table = Json::array();
  for (double threshold : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4}) {
    LocalIterationOptions local = options.local;
    local.gradient_threshold_mm = threshold;
    table.push_back(table_row(local, 1).first);
  }
  main["precompute_seconds"] = precompute_seconds;
  main["threshold_table"] = table;
  return main;
}

Json bench_msm(const CubeProblem& cube, const CubeBenchOptions& options, Eigen::MatrixX3d& displacement) {
  MassSpringModel model;
  double build_seconds = seconds_of([&] { model = make_van_gelder_model(cube.mesh, Material{}.young_modulus_mpa); });
  LocalIterationResult result;
  const double seconds =
      median_seconds(options.runs, [&] { result = solve_mass_spring(model, cube.bc, options.local); });
  displacement = result.displacement;
  Precision difference = precision_against(result.displacement, converged_fem(cube), free_mask(cube.bc));
  return {{"build_seconds", build_seconds},
          {"solve_seconds", seconds},
          {"iterations", result.iterations},
          {"point_updates", result.point_updates},
          {"load_steps", result.load_steps},
          {"converged", result.status == IterationStatus::kConverged},
          {"difference_from_fem_worst_mm", difference.worst_mm},
          {"difference_from_fem_mean_mm", difference.mean_mm}};
}

// Non-linear FEM (neo-Hookean, Newton): 6 mm on a 100 mm cube is a small strain, so it
// stays close to linear FEM; the difference is the geometric non-linearity.
Json bench_nfem(const CubeProblem& cube, const CubeBenchOptions& options, Eigen::MatrixX3d& displacement) {
  NewtonOptions newton;
  newton.load_steps = 1;
  NonlinearSolution result;
  const double seconds =
      median_seconds(options.runs, [&] { result = solve_nonlinear_static(cube.mesh, Material{}, cube.bc, newton); });
  displacement = result.displacement;
  Precision difference = precision_against(result.displacement, converged_fem(cube), free_mask(cube.bc));
  return {{"solve_seconds", seconds},
          {"newton_iterations", result.newton_iterations},
          {"linear_iterations", result.linear_iterations},
          {"converged", result.converged},
          {"relative_residual", result.relative_residual},
          {"difference_from_fem_worst_mm", difference.worst_mm},
          {"difference_from_fem_mean_mm", difference.mean_mm}};
}

Json bench_model(const CubeProblem& cube, const CubeBenchOptions& options, Eigen::MatrixX3d& displacement) {
  switch (options.model) {
    case SoftTissueModel::kLinearFem: return bench_fem(cube, options, displacement);
    case SoftTissueModel::kMassTensor: return bench_mtm(cube, options, displacement);
    case SoftTissueModel::kMassSpring: return bench_msm(cube, options, displacement);
    case SoftTissueModel::kNonlinearFem: return bench_nfem(cube, options, displacement);
  }
  throw Error(ErrorCode::kBadValue, "bench cube", "unknown model");
}

// The mass tensor model's precision and cost at each local stop threshold.
std::string threshold_table_text(const Json& table) {
  std::string text = formatted("%-10s %8s %10s %12s %10s %10s %8s\n", "G_thresh", "its", "updates", "seconds", "P_min",
                               "P_mean", "conv");
  for (const auto& row : table)
    text += formatted("%-10.0e %8d %10ld %12.4f %10.4f %10.4f %8s\n", row["gradient_threshold_mm"].get<double>(),
                      row["iterations"].get<int>(), row["point_updates"].get<long>(),
                      row["solve_seconds"].get<double>(), row["precision_worst_mm"].get<double>(),
                      row["precision_mean_mm"].get<double>(), row["converged"].get<bool>() ? "yes" : "no");
  return text;
}

}  // namespace

Json run_cube_benchmark(const CubeBenchOptions& options) {
  const CubeProblem cube = make_cube_problem(options);
  const MeshQuality quality = mesh_quality(cube.mesh);
  Eigen::MatrixX3d displacement;
  Json result = bench_model(cube, options, displacement);
  if (!options.out.empty()) write_vtu(options.out, cube.mesh, displacement, cube.bc);
  return {{"model", std::string(model_name(options.model))},
          {"tets", cube.mesh.tet_count()},
          {"nodes", cube.mesh.node_count()},
          {"divisions", cube.spec.divisions},
          {"free_nodes", count_nodes(cube.bc, NodeConstraint::kFree)},
          {"prescribed_nodes", count_nodes(cube.bc, NodeConstraint::kPrescribed)},
          {"min_dihedral_deg", quality.min_dihedral_deg},
          {"max_aspect_ratio", quality.max_aspect_ratio},
          {"assembly_seconds", cube.assembly_seconds},
          {"runs", options.runs},
          {"max_displacement_mm", displacement.rowwise().norm().maxCoeff()},
          {"model_result", result}};
}

std::string cube_benchmark_text(const Json& figures) {
  std::string text;
  for (const auto& [key, value] : figures.items())
    if (!value.is_object() && !value.is_array()) text += key + ": " + value.dump() + "\n";
  const Json& model = figures["model_result"];
  for (const auto& [key, value] : model.items())
    if (!value.is_array()) text += key + ": " + value.dump() + "\n";
  if (model.contains("threshold_table")) text += threshold_table_text(model["threshold_table"]);
  return text;
}

}  // namespace maxillo::bench
