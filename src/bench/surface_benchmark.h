#pragma once
// What `maxillo bench surfaces` measures (issue 16): a clinical-size volume through segmentation,
// skin and bone, with seconds per stage and the process's peak memory; optionally the same
// surfaces traced on the CT's own grid (SurfaceGrid::Native, the former path) for comparison:
// their time, and how far the default surfaces lie from them.
#include <optional>
#include <string>

#include "core/volume.h"
#include "casework/case_surfaces.h"
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

// Peak resident memory of this process so far, kB (getrusage).
long peak_memory_kb();

// Resets the kernel's high-water mark of this process's resident memory to what it holds now
// ("5" written to /proc/self/clear_refs), so that resident_peak_kb() then measures one step.
// False where that cannot be done.
bool reset_resident_peak();
long resident_peak_kb();  // VmHWM of /proc/self/status, kB; 0 if unreadable

}  // namespace maxillo::bench
