// maxillo bench cube --tets N --model fem|mtm|msm|nfem [--out cube.vtu]: the thesis' cube test
// (ch. 6, fig. 2): a cube (100 mm) with its border fixed and its centre (20 mm) moved 6 mm
// upward. Prints set-up and solve times (median of --runs), iterations and the precision
// against the fully converged linear FEM answer (tight-tolerance conjugate gradient).
// Targets (issue 3, ~105,000 tets): linear FEM <= 0.15 s, mass tensor <= 0.5 s at
// P_min <= 0.3 mm, re-solve after a plan change <= 30 ms.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>

#include "cli/command.h"
#include "core/error.h"
#include "core/json.h"
#include "softtissue/blas_library.h"
#include "softtissue/cube_benchmark.h"
#include "softtissue/element_quality.h"
#include "softtissue/factorised_elasticity.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/mass_spring_model.h"
#include "softtissue/mass_tensor_model.h"
#include "softtissue/nonlinear_fem.h"
#include "softtissue/rigid_plan_basis.h"
#include "softtissue/vtu_writer.h"

namespace maxillo::cli {
namespace {

using namespace maxillo::softtissue;

enum class CubeModel { kFem, kMtm, kMsm, kNfem };

struct CubeBenchArguments {
  int tets = 105000;
  CubeModel model = CubeModel::kFem;
  HexSplit split = HexSplit::kSixTets;
  Preconditioner preconditioner = Preconditioner::kBlockJacobi;
  CholeskyBackend cholesky =
      cholmod_available() ? CholeskyBackend::kCholmodSupernodal : CholeskyBackend::kEigenSimplicial;
  double tolerance = 1e-6;
  LocalIterationOptions local{1e-3, 1.0, 1000000};
  int runs = 5;
  std::filesystem::path out;
};

struct CubeProblem {
  CubeSpec spec;
  TetMesh mesh;
  BoundaryConditions bc;
  StiffnessBlocks stiffness;
  double assembly_seconds = 0;
};

template <class Work>
double seconds_of(Work&& work) {
  auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
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

Json bench_fem(const CubeProblem& cube, const CubeBenchArguments& args, Eigen::MatrixX3d& displacement) {
  std::vector<double> times;
  StaticSolution solution;
  for (int run = 0; run < args.runs; ++run)
    times.push_back(seconds_of([&] {
      solution = solve_linear_static(cube.stiffness, cube.bc, {args.preconditioner, args.tolerance, 100000});
    }));
  if (solution.status != SolveStatus::kConverged)
    throw Error(ErrorCode::kProcessing, "bench cube", "the conjugate gradient did not converge");
  Precision precision = precision_against(solution.displacement, converged_fem(cube), free_mask(cube.bc));
  FactorisedElasticity factorised;
  std::vector<double> factorise_times;
  for (int run = 0; run < args.runs; ++run)
    factorise_times.push_back(seconds_of([&] {
      if (precompute_factorisation(cube.stiffness, cube.bc.constraint, args.cholesky, factorised) !=
          FactorisationStatus::kOk)
        throw Error(ErrorCode::kProcessing, "bench cube", "the Cholesky factorisation failed or is not built in");
    }));
  // Plan changes: the centre's lift varies, the constraint pattern stays.
  std::vector<double> resolve_times;
  BoundaryConditions changed = cube.bc;
  for (int run = 0; run < std::max(args.runs, 3); ++run) {
    for (int i = 0; i < changed.node_count(); ++i)
      if (changed.constraint[size_t(i)] == NodeConstraint::kPrescribed) changed.displacement(i, 2) = 6.0 - 0.5 * run;
    resolve_times.push_back(seconds_of([&] { displacement = solve_factorised(factorised, changed); }));
  }
  displacement = solve_factorised(factorised, cube.bc);
  // The rigid-plan fast path: the centre is one bone segment; a plan change is a new motion.
  std::vector<int> segment(size_t(cube.mesh.node_count()), 0);
  RigidPlanBasis basis;
  double basis_seconds =
      seconds_of([&] { basis = precompute_rigid_plan_basis(factorised, cube.mesh, cube.bc.constraint, segment, 1); });
  std::vector<double> plan_times;
  Eigen::MatrixX3d planned;
  for (int run = 0; run < std::max(args.runs, 3); ++run) {
    std::vector<Eigen::Isometry3d> motion(1, Eigen::Isometry3d::Identity());
    motion[0]
        .rotate(Eigen::AngleAxisd(0.05 * run, Eigen::Vector3d::UnitX()))
        .pretranslate(Eigen::Vector3d(0, 0, 6.0 - run));
    plan_times.push_back(seconds_of([&] { planned = solve_rigid_plan(basis, motion); }));
  }
  std::vector<Eigen::Isometry3d> lift(1, Eigen::Isometry3d::Identity());
  lift[0].pretranslate(Eigen::Vector3d(0, 0, 6.0));
  const double basis_error = (solve_rigid_plan(basis, lift) - displacement).cwiseAbs().maxCoeff();
  return {{"solve_seconds", median(times)},
          {"iterations", solution.iterations},
          {"relative_residual", solution.relative_residual},
          {"precision_worst_mm", precision.worst_mm},
          {"precision_mean_mm", precision.mean_mm},
          {"factorise_seconds", median(factorise_times)},
          {"factor_nonzeros", factorised.factor_nonzeros},
          {"blas", blas_library()},
          {"cholesky", factorised.backend == CholeskyBackend::kCholmodSupernodal ? "cholmod" : "eigen"},
          {"resolve_seconds", median(resolve_times)},
          {"rigid_plan_basis_seconds", basis_seconds},
          {"rigid_plan_resolve_seconds", median(plan_times)},
          {"rigid_plan_vs_resolve_max_mm", basis_error}};
}

Json bench_mtm(const CubeProblem& cube, const CubeBenchArguments& args, Eigen::MatrixX3d& displacement) {
  MassTensorModel model;
  double precompute_seconds = seconds_of([&] { model = make_mass_tensor_model(cube.stiffness); });
  const Eigen::MatrixX3d converged = converged_fem(cube);
  auto table_row = [&](const LocalIterationOptions& options, int runs) {
    std::vector<double> times;
    LocalIterationResult result;
    for (int run = 0; run < runs; ++run)
      times.push_back(seconds_of([&] { result = solve_mass_tensor(model, cube.bc, options); }));
    Precision precision = precision_against(result.displacement, converged, free_mask(cube.bc));
    return std::pair{Json{{"gradient_threshold_mm", options.gradient_threshold_mm},
                          {"relaxation", options.relaxation},
                          {"solve_seconds", median(times)},
                          {"iterations", result.iterations},
                          {"point_updates", result.point_updates},
                          {"precision_worst_mm", precision.worst_mm},
                          {"precision_mean_mm", precision.mean_mm},
                          {"converged", result.status == IterationStatus::kConverged}},
                     result.displacement};
  };
  auto [main, main_displacement] = table_row(args.local, args.runs);
  displacement = main_displacement;
  Json table = Json::array();
  for (double threshold : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4}) {
    LocalIterationOptions options = args.local;
    options.gradient_threshold_mm = threshold;
    table.push_back(table_row(options, 1).first);
  }
  main["precompute_seconds"] = precompute_seconds;
  main["threshold_table"] = table;
  return main;
}

Json bench_msm(const CubeProblem& cube, const CubeBenchArguments& args, Eigen::MatrixX3d& displacement) {
  MassSpringModel model;
  double build_seconds = seconds_of([&] { model = make_van_gelder_model(cube.mesh, Material{}.young_modulus_mpa); });
  std::vector<double> times;
  LocalIterationResult result;
  for (int run = 0; run < args.runs; ++run)
    times.push_back(seconds_of([&] { result = solve_mass_spring(model, cube.bc, args.local); }));
  displacement = result.displacement;
  Precision difference = precision_against(result.displacement, converged_fem(cube), free_mask(cube.bc));
  return {{"build_seconds", build_seconds},
          {"solve_seconds", median(times)},
          {"iterations", result.iterations},
          {"point_updates", result.point_updates},
          {"load_steps", result.load_steps},
          {"converged", result.status == IterationStatus::kConverged},
          {"difference_from_fem_worst_mm", difference.worst_mm},
          {"difference_from_fem_mean_mm", difference.mean_mm}};
}

// Non-linear FEM (neo-Hookean, Newton): 6 mm on a 100 mm cube is a small strain, so it
// stays close to linear FEM; the difference is the geometric non-linearity.
Json bench_nfem(const CubeProblem& cube, const CubeBenchArguments& args, Eigen::MatrixX3d& displacement) {
  NewtonOptions options;
  options.load_steps = 1;
  std::vector<double> times;
  NonlinearSolution result;
  for (int run = 0; run < args.runs; ++run)
    times.push_back(seconds_of([&] { result = solve_nonlinear_static(cube.mesh, Material{}, cube.bc, options); }));
  displacement = result.displacement;
  Precision difference = precision_against(result.displacement, converged_fem(cube), free_mask(cube.bc));
  return {{"solve_seconds", median(times)},
          {"newton_iterations", result.newton_iterations},
          {"linear_iterations", result.linear_iterations},
          {"converged", result.converged},
          {"relative_residual", result.relative_residual},
          {"difference_from_fem_worst_mm", difference.worst_mm},
          {"difference_from_fem_mean_mm", difference.mean_mm}};
}

void print_text(const Json& summary) {
  for (const auto& [key, value] : summary.items()) {
    if (value.is_object() || value.is_array()) continue;
    std::cout << key << ": " << value.dump() << "\n";
  }
  if (summary.contains("model_result")) {
    for (const auto& [key, value] : summary["model_result"].items())
      if (!value.is_array()) std::cout << key << ": " << value.dump() << "\n";
    if (summary["model_result"].contains("threshold_table")) {
      std::printf("%-10s %8s %10s %12s %10s %10s %8s\n", "G_thresh", "its", "updates", "seconds", "P_min", "P_mean",
                  "conv");
      for (const auto& row : summary["model_result"]["threshold_table"])
        std::printf("%-10.0e %8d %10ld %12.4f %10.4f %10.4f %8s\n", row["gradient_threshold_mm"].get<double>(),
                    row["iterations"].get<int>(), row["point_updates"].get<long>(), row["solve_seconds"].get<double>(),
                    row["precision_worst_mm"].get<double>(), row["precision_mean_mm"].get<double>(),
                    row["converged"].get<bool>() ? "yes" : "no");
    }
  }
}

void run_bench_cube(const CubeBenchArguments& args, const CommandContext& ctx) {
  CubeProblem cube;
  cube.spec = {100.0, cube_divisions_for_tets(args.tets, args.split), args.split};
  cube.mesh = make_cube_mesh(cube.spec);
  cube.bc = cube_benchmark_conditions(cube.mesh, cube.spec);
  cube.assembly_seconds = seconds_of([&] { cube.stiffness = assemble_stiffness_blocks(cube.mesh, Material{}); });
  MeshQuality quality = mesh_quality(cube.mesh);
  Eigen::MatrixX3d displacement;
  static const std::map<CubeModel, std::string> names{
      {CubeModel::kFem, "fem"}, {CubeModel::kMtm, "mtm"}, {CubeModel::kMsm, "msm"}, {CubeModel::kNfem, "nfem"}};
  Json result = args.model == CubeModel::kFem   ? bench_fem(cube, args, displacement)
                : args.model == CubeModel::kMtm ? bench_mtm(cube, args, displacement)
                : args.model == CubeModel::kMsm ? bench_msm(cube, args, displacement)
                                                : bench_nfem(cube, args, displacement);
  Json summary{{"model", names.at(args.model)},
               {"tets", cube.mesh.tet_count()},
               {"nodes", cube.mesh.node_count()},
               {"divisions", cube.spec.divisions},
               {"free_nodes", count_nodes(cube.bc, NodeConstraint::kFree)},
               {"prescribed_nodes", count_nodes(cube.bc, NodeConstraint::kPrescribed)},
               {"min_dihedral_deg", quality.min_dihedral_deg},
               {"max_aspect_ratio", quality.max_aspect_ratio},
               {"assembly_seconds", cube.assembly_seconds},
               {"runs", args.runs},
               {"max_displacement_mm", displacement.rowwise().norm().maxCoeff()},
               {"model_result", result}};
  if (!args.out.empty()) write_vtu(args.out, cube.mesh, displacement, cube.bc);
  if (ctx.global.json)
    std::cout << summary.dump(2) << "\n";
  else
    print_text(summary);
}

}  // namespace

void attach_bench_cube(CLI::App& bench, CommandContext& ctx) {
  CLI::App* cube = bench.add_subcommand("cube", "soft tissue cube test: border fixed, centre lifted 6 mm");
  auto args = std::make_shared<CubeBenchArguments>();
  std::map<std::string, CubeModel> models{
      {"fem", CubeModel::kFem}, {"mtm", CubeModel::kMtm}, {"msm", CubeModel::kMsm}, {"nfem", CubeModel::kNfem}};
  std::map<std::string, HexSplit> splits{{"5", HexSplit::kFiveTets}, {"6", HexSplit::kSixTets}};
  std::map<std::string, Preconditioner> preconditioners{{"block-jacobi", Preconditioner::kBlockJacobi},
                                                        {"jacobi", Preconditioner::kJacobi},
                                                        {"ic", Preconditioner::kIncompleteCholesky}};
  std::map<std::string, CholeskyBackend> backends{{"eigen", CholeskyBackend::kEigenSimplicial},
                                                  {"cholmod", CholeskyBackend::kCholmodSupernodal}};
  cube->add_option("--tets", args->tets, "approximate number of tetrahedra")->check(CLI::Range(6, 5000000));
  cube->add_option("--model", args->model,
                   "fem (linear FEM), mtm (mass tensor), msm (mass-spring), nfem (non-linear FEM)")
      ->required()
      ->transform(CLI::CheckedTransformer(models, CLI::ignore_case));
  cube->add_option("--split", args->split, "tets per hexahedron: 5 or 6")->transform(CLI::CheckedTransformer(splits));
  cube->add_option("--preconditioner", args->preconditioner,
                   "fem: block-jacobi (matrix-free, default), jacobi or ic (incomplete Cholesky)")
      ->transform(CLI::CheckedTransformer(preconditioners, CLI::ignore_case));
  cube->add_option("--cholesky", args->cholesky, "fem re-solve factorisation: eigen or cholmod (default when built in)")
      ->transform(CLI::CheckedTransformer(backends, CLI::ignore_case));
  cube->add_option("--tolerance", args->tolerance, "fem: relative residual of the conjugate gradient")
      ->check(CLI::Range(1e-15, 1e-1));
  cube->add_option("--threshold", args->local.gradient_threshold_mm, "mtm/msm: local stop threshold, mm per iteration")
      ->check(CLI::Range(0.0, 10.0));
  cube->add_option("--relaxation", args->local.relaxation, "mtm/msm: over-relaxation of the point update, in [1, 2)")
      ->check(CLI::Range(1.0, 1.99));
  cube->add_option("--runs", args->runs, "timed runs; the median is reported")->check(CLI::Range(1, 100));
  cube->add_option("--out", args->out, "write the mesh, displacement and bc as a .vtu file");
  cube->callback([args, &ctx] { run_bench_cube(*args, ctx); });
}

}  // namespace maxillo::cli
