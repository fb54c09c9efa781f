// maxillo bench landmarks [--patients 30] [--cone-beam-every 3] [--spacing MM] [--id-prefix BENCH-]: the automatic
// landmarks against the truth of many varied phantoms (bench/landmark_benchmark.h).
#include <iostream>

#include "bench/landmark_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {

void attach_bench_landmarks(CLI::App& bench, CommandContext& ctx) {
  CLI::App* landmarks =
      bench.add_subcommand("landmarks", "automatic landmarks on varied phantoms: radial error per landmark, s and MB");
  auto args = std::make_shared<bench::LandmarkBenchOptions>();
  landmarks->add_option("--patients", args->patients, "phantom patients, each drawn from its Patient ID")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  landmarks->add_option("--cone-beam-every", args->cone_beam_every, "every n-th patient a cone-beam scan (0: none)")
      ->check(CLI::Range(0, 10000))
      ->capture_default_str();
  landmarks->add_option("--spacing", args->spacing_mm, "one voxel spacing for all (default: drawn per patient)")
      ->check(CLI::Range(0.25, 4.0));
  landmarks->add_option("--id-prefix", args->id_prefix, "Patient IDs: this prefix and 001, 002, ...")
      ->capture_default_str();
  landmarks->callback([args, &ctx] {
    const auto runs = bench::run_landmark_benchmark(*args);
    std::cout << (ctx.global.json ? json_text(bench::landmark_benchmark_json(runs)) + "\n"
                                  : bench::landmark_benchmark_text(runs));
  });
}

}  // namespace maxillo::cli
