#include "bench/surface_benchmark.h"

#include <algorithm>
#include <string>
#include <vector>

#include "bench/formatted.h"
#include "bench/peak_memory.h"
#include "bench/registration_benchmark.h"
#include "bench/shared_data.h"
#include "bench/timing.h"
#include "geometry/mesh_measures.h"
#include "imaging/volume_assembly.h"
#include "sample/phantom.h"

namespace maxillo::bench {
namespace {

SurfacePair pair_of(const casework::CaseSurfaces& surfaces, const casework::SurfaceTimes& times) {
  return {times.skin, times.bone, surfaces.skin.face_count(), surfaces.bone.face_count(),
          connected_components(surfaces.bone).face_counts.size()};
}

// The volume asked for; `name` says which, `seconds` how long it took to read or make.
Volume load(const SurfaceBenchOptions& options, std::string& name, double& seconds) {
  const auto start = Clock::now();
  Volume volume;
  if (options.cadaver) {
    name = "cadaver head";
    volume = read_cadaver_head(shared_data_folder() / "cthead-stanford" / "slices");
  } else if (!options.series.empty()) {
    name = options.series.string();
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(options.series)) files.push_back(entry.path());
    volume = load_series_volume(files);
  } else {
    name = formatted("phantom at %.2f mm", options.phantom_spacing);
    PhantomSpec spec;
    spec.spacing_mm = options.phantom_spacing;
    volume = make_phantom(spec).ct;
  }
  seconds = seconds_since(start);
  return volume;
}

Json pair_json(const SurfacePair& p) {
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

Json benchmark_json(const std::string& name, const SurfaceBenchmark& result) {
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
  return json;
}

// The native grid's times, and how far the default surfaces lie from its.
std::string native_text(const Json& native) {
  const Json& surfaces = native["surfaces"];
  std::string text =
      formatted("native grid: skin %.2f s, bone %.2f s (%zu pieces)\n", surfaces["skin_seconds"].get<double>(),
                surfaces["bone_seconds"].get<double>(), surfaces["bone_pieces"].get<size_t>());
  for (const char* what : {"skin", "bone"}) {
    const Json& d = native[std::string(what) + "_distance"];
    text +=
        formatted("  %s against the native grid's: mean |d| %.3f mm, mean %+.3f mm, P5 %+.3f, P95 %+.3f, max %.3f mm\n",
                  what, d["mean_abs_mm"].get<double>(), d["mean_mm"].get<double>(), d["p5_mm"].get<double>(),
                  d["p95_mm"].get<double>(), d["max_abs_mm"].get<double>());
  }
  return text;
}

}  // namespace

SurfaceBenchmark benchmark_surfaces(const Volume& volume, double load_seconds, bool compare_native,
                                    const casework::SurfaceRecipe& recipe) {
  SurfaceBenchmark result;
  result.geometry = volume.geometry;
  result.load_seconds = load_seconds;
  casework::SurfaceTimes times;
  const long peak_before = peak_memory_kb();  // the reset below clears getrusage's maximum too
  const bool step_peak = reset_resident_peak();
  const casework::CaseSurfaces surfaces = casework::extract_case_surfaces(volume, recipe, &times);
  if (step_peak) result.surfaces_peak_memory_kb = resident_peak_kb();
  result.segmentation_seconds = times.segmentation;
  result.total_seconds = times.total;
  result.surfaces = pair_of(surfaces, times);
  result.peak_memory_kb = std::max(peak_before, peak_memory_kb());
  if (!compare_native) return result;

  casework::SurfaceRecipe native_recipe = recipe;
  native_recipe.skin.grid = native_recipe.bone.grid = SurfaceGrid::Native;
  casework::SurfaceTimes native_times;
  const casework::CaseSurfaces native = casework::extract_case_surfaces(volume, native_recipe, &native_times);
  NativeComparison comparison;
  comparison.native = pair_of(native, native_times);
  comparison.skin = validation::distance_statistics(validation::signed_surface_distances(surfaces.skin, native.skin));
  comparison.bone = validation::distance_statistics(validation::signed_surface_distances(surfaces.bone, native.bone));
  result.native = comparison;
  return result;
}

Json run_surface_benchmark(const SurfaceBenchOptions& options) {
  std::string name;
  double seconds = 0;
  const Volume volume = load(options, name, seconds);
  return benchmark_json(name, benchmark_surfaces(volume, seconds, options.compare_native));
}

std::string surface_benchmark_text(const Json& figures) {
  const Json &size = figures["size"], &spacing = figures["spacing_mm"], &surfaces = figures["surfaces"];
  std::string text =
      formatted("%s: %d x %d x %d voxels (%.1f million), %.2f x %.2f x %.2f mm; read in %.2f s\n",
                figures["input"].get<std::string>().c_str(), size[0].get<int>(), size[1].get<int>(), size[2].get<int>(),
                double(figures["voxels"].get<int64_t>()) / 1e6, spacing[0].get<double>(), spacing[1].get<double>(),
                spacing[2].get<double>(), figures["load_seconds"].get<double>());
  text += formatted(
      "segmentation %.2f s, skin %.2f s (%lld triangles), bone %.2f s (%lld triangles, %zu pieces); "
      "total %.2f s (wall; skin and bone at once); peak memory %.0f MB while segmenting and tracing "
      "(the volume included), %.0f MB for the whole process\n",
      figures["segmentation_seconds"].get<double>(), surfaces["skin_seconds"].get<double>(),
      surfaces["skin_triangles"].get<long long>(), surfaces["bone_seconds"].get<double>(),
      surfaces["bone_triangles"].get<long long>(), surfaces["bone_pieces"].get<size_t>(),
      figures["total_seconds"].get<double>(), figures["surfaces_peak_memory_mb"].get<double>(),
      figures["peak_memory_mb"].get<double>());
  return figures.contains("native") ? text + native_text(figures["native"]) : text;
}

}  // namespace maxillo::bench
