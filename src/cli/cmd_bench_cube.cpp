// maxillo bench cube --tets N --model fem|mtm|msm|nfem [--out cube.vtu]: the thesis' cube test,
// border fixed and centre lifted 6 mm, with each soft tissue model (bench/cube_benchmark.h).
#include <iostream>
#include <map>

#include "bench/cube_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {

void attach_bench_cube(CLI::App& bench, CommandContext& ctx) {
  using namespace maxillo::softtissue;
  CLI::App* cube = bench.add_subcommand("cube", "soft tissue cube test: border fixed, centre lifted 6 mm");
  auto args = std::make_shared<bench::CubeBenchOptions>();
  std::map<std::string, SoftTissueModel> models;
  for (const auto& m : soft_tissue_models()) models.emplace(std::string(m.name), m.model);
  std::map<std::string, HexSplit> splits{{"5", HexSplit::kFiveTets}, {"6", HexSplit::kSixTets}};
  std::map<std::string, Preconditioner> preconditioners{{"block-jacobi", Preconditioner::kBlockJacobi},
                                                        {"jacobi", Preconditioner::kJacobi},
                                                        {"ic", Preconditioner::kIncompleteCholesky}};
  std::map<std::string, CholeskyBackend> backends{{"eigen", CholeskyBackend::kEigenSimplicial},
                                                  {"cholmod", CholeskyBackend::kCholmodSupernodal}};
  cube->add_option("--tets", args->tets, "approximate number of tetrahedra")->check(CLI::Range(6, 5000000));
  cube->add_option("--model", args->model, model_choices())
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
  cube->add_flag("--calculix", args->calculix,
                 "fem: CalculiX (ccx) on the same cube too: its seconds, its difference, the speed ratio");
  cube->add_option("--out", args->out, "write the mesh, displacement and bc as a .vtu file");
  cube->callback([args, &ctx] {
    const Json figures = bench::run_cube_benchmark(*args);
    std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::cube_benchmark_text(figures));
  });
}

}  // namespace maxillo::cli
