#pragma once
// `maxillo bench occlusion`: guided alignment on the real teeth of openfulljaw-p26-teeth (upper
// and lower arches scanned in natural occlusion). For each pose: the upper arch is displaced by
// a random rigid motion (rotation up to 5 degrees about its centre, translation up to 3 mm),
// moved along z into contact (penetrating the lower arch as deep as the natural occlusion does,
// which scan noise makes ~0.3 mm: with less, the engine's rule "no deeper than the start +
// 0.05 mm" would forbid the natural occlusion itself), then pulled back by 4 springs between
// points where the teeth touch in the natural occlusion. Score: P95 of the displacement between
// the final and the natural pose over the occlusal region (upper vertices within 3 mm of the
// lower arch).
// Target (issue 6): P95 <= 0.3 mm, median time <= 1 s per pose.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/json.h"

namespace maxillo::bench {

struct OcclusionBenchOptions {
  int poses = 100;  // random starting poses
  unsigned seed = 1;
  // The folder with upper_teeth_merged.stl and lower_teeth_merged.stl; empty: the shared data's
  // openfulljaw-p26-teeth.
  std::filesystem::path data;
};

// One starting pose and where the guided alignment took the upper arch.
struct PoseResult {
  double start_p95_mm = 0, p95_mm = 0;  // from the natural pose, over the occlusal region
  double penetration_mm = 0, allowed_mm = 0;
  int iterations = 0;
  bool converged = false;  // false: stopped at the iteration limit
  double seconds = 0;
};

struct OcclusionBenchmark {
  std::string skipped;  // why it did not run (the teeth are absent); empty when it ran
  unsigned seed = 1;
  int64_t upper_vertices = 0, lower_vertices = 0;
  size_t region_vertices = 0;  // the occlusal region's upper vertices
  double natural_penetration_mm = 0;
  double distance_fields_seconds = 0;  // BVH and pseudo-normals, once per arch
  std::vector<PoseResult> poses;
};

// Skipped (with the reason) when the teeth are not in the data folder.
OcclusionBenchmark run_occlusion_benchmark(const OcclusionBenchOptions& options);

// The figures of a run that was not skipped: poses, seed, upper_vertices, lower_vertices,
// occlusal_region_vertices, natural_penetration_mm, distance_fields_seconds, p95_mm and seconds
// over the poses (median, p90, max), poses_within_0_3_mm, penetration_limit_violations.
Json occlusion_benchmark_json(const OcclusionBenchmark& benchmark);

// As `bench occlusion` prints it: a line per pose, then the arches and the scores; or the
// reason it was skipped.
std::string occlusion_benchmark_text(const OcclusionBenchmark& benchmark);

}  // namespace maxillo::bench
