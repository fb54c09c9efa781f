// maxillo bench dental [--starts 20] [--seed 1] [--data DIR]: a simulated intraoral scan of real
// teeth registered onto them from random starts (bench/dental_benchmark.h).
#include <iostream>

#include "bench/dental_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

void print(const bench::DentalBenchmark& result, const CommandContext& ctx) {
  if (ctx.global.json && result.skipped.empty())
    std::cout << json_text(bench::dental_benchmark_json(result)) << "\n";
  else  // a skipped run has no figures: the reason, in words, --json or not
    std::cout << bench::dental_benchmark_text(result);
}

}  // namespace

void attach_bench_dental(CLI::App& bench, CommandContext& ctx) {
  CLI::App* dental = bench.add_subcommand(
      "dental", "dental scan registration onto real teeth from random starts (mm from the truth, s/arch)");
  auto args = std::make_shared<bench::DentalBenchOptions>();
  dental->add_option("--starts", args->starts, "random starts per arch")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  dental->add_option("--seed", args->seed, "random seed")->capture_default_str();
  dental->add_option("--data", args->data,
                     "folder with upper_teeth_merged.stl, lower_teeth_merged.stl, maxilla/, mandible/ "
                     "(default: $MAXILLO_SHARED_DATA or ../shared/data, /openfulljaw-p26-teeth)");
  dental->callback([args, &ctx] { print(bench::run_dental_benchmark(*args), ctx); });
}

}  // namespace maxillo::cli
