// maxillo bench surfaces [--phantom-spacing MM | --cadaver | --series DIR] [--compare-native]:
// a clinical-size volume through segmentation, skin and bone (pipeline/surface_benchmark.h):
// voxels, seconds per stage, peak memory; with --compare-native also the former path (surfaces
// on the CT's own grid): its time and how far the default surfaces lie from it.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "cli/command.h"
#include "core/error.h"
#include "core/json.h"
#include "imaging/volume_assembly.h"
#include "bench/registration_benchmark.h"
#include "bench/surface_benchmark.h"
#include "sample/phantom.h"

namespace maxillo::cli {
namespace {

struct SurfacesBenchArguments {
  double phantom_spacing = 0.5;
  bool cadaver = false;
  std::filesystem::path series;
  bool compare_native = false;
};

std::filesystem::path cadaver_slices() {
  const char* shared = std::getenv("MAXILLO_SHARED_DATA");
  return std::filesystem::path(shared ? shared : "../shared/data") / "cthead-stanford" / "slices";
}

// The volume asked for, and the seconds it took to read or make.
Volume load(const SurfacesBenchArguments& args, std::string& name, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  Volume volume;
  if (args.cadaver) {
    name = "cadaver head";
    volume = bench::read_cadaver_head(cadaver_slices());
  } else if (!args.series.empty()) {
    name = args.series.string();
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(args.series)) files.push_back(entry.path());
    volume = load_series_volume(files);
  } else {
    char text[64];
    std::snprintf(text, sizeof text, "phantom at %.2f mm", args.phantom_spacing);
    name = text;
    PhantomSpec spec;
    spec.spacing_mm = args.phantom_spacing;
    volume = make_phantom(spec).ct;
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return volume;
}

Json pair_json(const bench::SurfacePair& p) {
  return {{"skin_seconds", p.skin_seconds},
          {"bone_seconds", p.bone_seconds},
          {"skin_triangles", p.skin_triangles},
          {"bone_triangles", p.bone_triangles},
          {"bone_pieces", p.bone_pieces}};
}

Json distances_json(const validation::DistanceStatistics& d) {
  return {{"mean_abs_mm", d.mean_absolute},
          {"mean_mm", d.mean_signed},
          {"p5_mm", d.p5},
          {"p95_mm", d.p95},
          {"max_abs_mm", d.max_absolute}};
}

void print(const std::string& name, const bench::SurfaceBenchmark& b) {
  const auto& g = b.geometry;
  std::printf("%s: %d x %d x %d voxels (%.1f million), %.2f x %.2f x %.2f mm; read in %.2f s\n", name.c_str(),
              g.size.x(), g.size.y(), g.size.z(), double(g.voxel_count()) / 1e6, g.spacing.x(), g.spacing.y(),
              g.spacing.z(), b.load_seconds);
  std::printf(
      "segmentation %.2f s, skin %.2f s (%lld triangles), bone %.2f s (%lld triangles, %zu pieces); "
      "total %.2f s (wall; skin and bone at once); peak memory %.0f MB while segmenting and tracing "
      "(the volume included), %.0f MB for the whole process\n",
      b.segmentation_seconds, b.surfaces.skin_seconds, (long long)b.surfaces.skin_triangles, b.surfaces.bone_seconds,
      (long long)b.surfaces.bone_triangles, b.surfaces.bone_pieces, b.total_seconds, b.surfaces_peak_memory_kb / 1024.0,
      b.peak_memory_kb / 1024.0);
  if (!b.native) return;
  const auto& n = *b.native;
  std::printf("native grid: skin %.2f s, bone %.2f s (%zu pieces)\n", n.native.skin_seconds, n.native.bone_seconds,
              n.native.bone_pieces);
  for (const auto& [what, d] : {std::pair{"skin", n.skin}, std::pair{"bone", n.bone}})
    std::printf("  %s against the native grid's: mean |d| %.3f mm, mean %+.3f mm, P5 %+.3f, P95 %+.3f, max %.3f mm\n",
                what, d.mean_absolute, d.mean_signed, d.p5, d.p95, d.max_absolute);
}

void run(const SurfacesBenchArguments& args, CommandContext& ctx) {
  std::string name;
  double seconds = 0;
  const Volume volume = load(args, name, seconds);
  const auto result = bench::benchmark_surfaces(volume, seconds, args.compare_native);
  if (!ctx.global.json) {
    print(name, result);
    return;
  }
  const auto& g = result.geometry;
  Json json = {{"input", name},
               {"size", {g.size.x(), g.size.y(), g.size.z()}},
               {"spacing_mm", {g.spacing.x(), g.spacing.y(), g.spacing.z()}},
               {"voxels", g.voxel_count()},
               {"load_seconds", result.load_seconds},
               {"segmentation_seconds", result.segmentation_seconds},
               {"total_seconds", result.total_seconds},
               {"surfaces", pair_json(result.surfaces)},
               {"peak_memory_mb", result.peak_memory_kb / 1024.0},
               {"surfaces_peak_memory_mb", result.surfaces_peak_memory_kb / 1024.0}};
  if (result.native)
    json["native"] = {{"surfaces", pair_json(result.native->native)},
                      {"skin_distance", distances_json(result.native->skin)},
                      {"bone_distance", distances_json(result.native->bone)}};
  std::cout << json_text(json) << "\n";
}

}  // namespace

void attach_bench_surfaces(CLI::App& bench, CommandContext& ctx) {
  CLI::App* sub =
      bench.add_subcommand("surfaces", "segmentation, skin and bone of a clinical-size CT: s per stage, peak memory");
  auto args = std::make_shared<SurfacesBenchArguments>();
  sub->add_option("--phantom-spacing", args->phantom_spacing, "the synthetic phantom at this spacing (mm)")
      ->check(CLI::Range(0.25, 4.0))
      ->capture_default_str();
  sub->add_flag("--cadaver", args->cadaver, "the real cadaver head (../shared/data or MAXILLO_SHARED_DATA)");
  sub->add_option("--series", args->series, "a folder holding one DICOM CT series")->check(CLI::ExistingDirectory);
  sub->add_flag("--compare-native", args->compare_native,
                "also trace the surfaces on the CT's own grid: its time, and the distance between the two");
  sub->callback([args, &ctx] { run(*args, ctx); });
}

}  // namespace maxillo::cli
