// maxillo bench register [--data DIR] [--runs 3] [--rotation-deg 4] [--translation-mm 7]:
// rigid registration on the real cadaver head, ours against elastix: seconds and RMS error over
// the skin (bench/register_benchmark.h).
#include <iostream>

#include "bench/register_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

void print(const bench::RegisterBenchmark& result, const CommandContext& ctx) {
  if (ctx.global.json && result.skipped.empty())
    std::cout << json_text(bench::register_benchmark_json(result)) << "\n";
  else  // a skipped run has no figures: the reason, in words, --json or not
    std::cout << bench::register_benchmark_text(result);
}

}  // namespace

void attach_bench_register(CLI::App& bench, CommandContext& ctx) {
  CLI::App* sub =
      bench.add_subcommand("register", "rigid CT registration on the real head: ours vs elastix (s, RMS mm)");
  auto args = std::make_shared<bench::RegisterBenchOptions>();
  sub->add_option("--data", args->data,
                  "folder holding slices/CThead.* (default: $MAXILLO_SHARED_DATA or ../shared/data, /cthead-stanford)");
  sub->add_option("--runs", args->runs, "runs; medians are reported")->check(CLI::Range(1, 50))->capture_default_str();
  sub->add_option("--rotation-deg", args->rotation_deg, "known rotation, degrees")
      ->check(CLI::Range(0.0, 30.0))
      ->capture_default_str();
  sub->add_option("--translation-mm", args->translation_mm, "known translation, mm")
      ->check(CLI::Range(0.0, 50.0))
      ->capture_default_str();
  sub->add_flag("!--no-elastix", args->elastix, "run only ours");
  sub->add_option("--sampling-fraction", args->ours.sampling_fraction, "ours: fraction of each level's voxels sampled")
      ->check(CLI::Range(1e-4, 1.0))
      ->capture_default_str();
  sub->add_option("--convergence", args->ours.convergence,
                  "ours: full resolution stops when the last --window steps each moved the image less than this (mm)")
      ->check(CLI::Range(1e-12, 1.0))
      ->capture_default_str();
  sub->add_option("--coarse-convergence", args->ours.coarse_convergence,
                  "ours: shrunk levels stop when the metric's normalised slope over the window falls below this")
      ->check(CLI::Range(1e-12, 1.0))
      ->capture_default_str();
  sub->add_flag("!--random-sampling", args->ours.regular_sampling, "ours: random samples instead of a jittered grid");
  sub->add_option("--bins", args->ours.histogram_bins, "ours: Mattes histogram bins")
      ->check(CLI::Range(8, 256))
      ->capture_default_str();
  sub->add_option("--window", args->ours.convergence_window, "ours: convergence window (steps)")
      ->check(CLI::Range(3, 100))
      ->capture_default_str();
  sub->add_flag("--same-seed", args->same_seed, "every run samples alike: the spread is then non-determinism");
  sub->add_option("--threads", args->ours.threads, "ours: threads (0 = one per core; the answer is the same)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  sub->add_option("--levels", args->ours.levels, "ours: resolution levels")
      ->check(CLI::Range(1, 5))
      ->capture_default_str();
  sub->callback([args, &ctx] { print(bench::run_register_benchmark(*args), ctx); });
}

}  // namespace maxillo::cli
