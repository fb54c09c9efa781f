// maxillo bench surfaces [--phantom-spacing MM | --cadaver | --series DIR] [--compare-native]:
// a clinical-size volume through segmentation, skin and bone: voxels, seconds per stage, peak
// memory; with --compare-native also the surfaces on the CT's own grid (bench/surface_benchmark.h).
#include <iostream>

#include "bench/surface_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {

void attach_bench_surfaces(CLI::App& bench, CommandContext& ctx) {
  CLI::App* sub =
      bench.add_subcommand("surfaces", "segmentation, skin and bone of a clinical-size CT: s per stage, peak memory");
  auto args = std::make_shared<bench::SurfaceBenchOptions>();
  sub->add_option("--phantom-spacing", args->phantom_spacing, "the synthetic phantom at this spacing (mm)")
      ->check(CLI::Range(0.25, 4.0))
      ->capture_default_str();
  sub->add_flag("--cadaver", args->cadaver, "the real cadaver head (../shared/data or MAXILLO_SHARED_DATA)");
  sub->add_option("--series", args->series, "a folder holding one DICOM CT series")->check(CLI::ExistingDirectory);
  sub->add_flag("--compare-native", args->compare_native,
                "also trace the surfaces on the CT's own grid: its time, and the distance between the two");
  sub->callback([args, &ctx] {
    const Json figures = bench::run_surface_benchmark(*args);
    std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::surface_benchmark_text(figures));
  });
}

}  // namespace maxillo::cli
