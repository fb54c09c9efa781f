#pragma once
// What `maxillo bench surfaces` measures (issue 16): a clinical-size volume (the phantom, the
// cadaver head or a DICOM series) through segmentation, skin and bone, with voxels, seconds per
// stage and the process's peak memory; optionally the same surfaces traced on the CT's own grid
// (SurfaceGrid::Native, the former path) for comparison: their time, and how far the default
// surfaces lie from them.
#include <filesystem>
#include <optional>
#include <string>

#include "core/json.h"
#include "core/volume.h"
#include "casework/surfaces/case_surfaces.h"
#include "validation/distance_statistics.h"

namespace maxillo::bench {

struct SurfacePair {
  double skin_seconds = 0, bone_seconds = 0;
  int64_t skin_triangles = 0, bone_triangles = 0;
  size_t bone_pieces = 0;
};

struct NativeComparison {
  SurfacePair native;
  // Signed distance of the default surfaces' vertices to the native ones (mm, + outside).
  validation::DistanceStatistics skin, bone;
};

struct SurfaceBenchmark {
  VolumeGeometry geometry;
  double load_seconds = 0;  // reading or generating the volume
  double segmentation_seconds = 0;
  double total_seconds = 0;  // wall clock of segmentation and both surfaces (traced at once)
  SurfacePair surfaces;
  long peak_memory_kb = 0;  // of the process after the default path (before any comparison)
  // The highest resident memory while segmenting and tracing (the volume included), when the
  // kernel's high-water mark could be reset before (Linux); 0 otherwise. The process peak can come
  // from reading or generating the volume instead.
  long surfaces_peak_memory_kb = 0;
  std::optional<NativeComparison> native;
};

// Runs the default path on `volume` (already loaded, in load_seconds), then the native one when
// asked. The recipe is the one case_surfaces uses.
SurfaceBenchmark benchmark_surfaces(const Volume& volume, double load_seconds, bool compare_native,
                                    const casework::SurfaceRecipe& recipe = {});

struct SurfaceBenchOptions {
  double phantom_spacing = 0.5;  // the synthetic phantom at this spacing (mm), unless cadaver or series
  bool cadaver = false;          // the real cadaver head (the shared data's cthead-stanford)
  std::filesystem::path series;  // a folder holding one DICOM CT series
  bool compare_native = false;   // also the surfaces on the CT's own grid
};

// The volume asked for, loaded, through benchmark_surfaces. The figures: input (what was
// loaded), size, spacing_mm, voxels, load_seconds, segmentation_seconds, total_seconds,
// surfaces (skin_seconds, bone_seconds, skin_triangles, bone_triangles, bone_pieces),
// peak_memory_mb, surfaces_peak_memory_mb; with compare_native also native: its surfaces and
// the distances of the default ones to them (skin_distance, bone_distance: mean_abs_mm, mean_mm,
// p5_mm, p95_mm, max_abs_mm).
Json run_surface_benchmark(const SurfaceBenchOptions& options);

// The figures as `bench surfaces` prints them: the volume, the stages; with the native grid its
// times and distances.
std::string surface_benchmark_text(const Json& figures);

}  // namespace maxillo::bench
