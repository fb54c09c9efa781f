#include "bench/surface_benchmark.h"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <string>

#include "geometry/mesh_measures.h"

namespace maxillo::bench {
namespace {

SurfacePair pair_of(const casework::CaseSurfaces& surfaces, const casework::SurfaceTimes& times) {
  return {times.skin, times.bone, surfaces.skin.face_count(), surfaces.bone.face_count(),
          connected_components(surfaces.bone).face_counts.size()};
}

}  // namespace

long peak_memory_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

bool reset_resident_peak() {
  std::ofstream clear_refs("/proc/self/clear_refs");
  return bool(clear_refs << "5" << std::flush);
}

long resident_peak_kb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long value = 0;
  while (status >> key) {
    if (key == "VmHWM:" && status >> value) return value;
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 0;
}

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

}  // namespace maxillo::bench
