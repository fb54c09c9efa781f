// maxillo bench occlusion [--poses 100] [--seed 1] [--data DIR]: guided alignment on the real
// teeth from random starting poses, P95 mm and seconds per pose (bench/occlusion_benchmark.h).
#include <iostream>

#include "bench/occlusion_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

void print(const bench::OcclusionBenchmark& result, const CommandContext& ctx) {
  if (ctx.global.json && result.skipped.empty())
    std::cout << json_text(bench::occlusion_benchmark_json(result)) << "\n";
  else  // a skipped run has no figures: the reason, in words, --json or not
    std::cout << bench::occlusion_benchmark_text(result);
}

}  // namespace

void attach_bench_occlusion(CLI::App& bench, CommandContext& ctx) {
  CLI::App* occlusion =
      bench.add_subcommand("occlusion", "guided occlusion alignment on the real teeth (P95 mm, s/pose)");
  auto args = std::make_shared<bench::OcclusionBenchOptions>();
  occlusion->add_option("--poses", args->poses, "random starting poses")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  occlusion->add_option("--seed", args->seed, "random seed")->capture_default_str();
  occlusion->add_option("--data", args->data,
                        "folder with upper_teeth_merged.stl, lower_teeth_merged.stl "
                        "(default: $MAXILLO_SHARED_DATA or ../shared/data, /openfulljaw-p26-teeth)");
  occlusion->callback([args, &ctx] { print(bench::run_occlusion_benchmark(*args), ctx); });
}

}  // namespace maxillo::cli
