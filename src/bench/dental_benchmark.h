#pragma once
// `maxillo bench dental` (issue 30): the dental scan registration on a real patient's teeth
// (openfulljaw-p26-teeth). Each arch's crowns are cut from its CBCT-segmented teeth into a
// simulated intraoral scan (sample/simulated_dental_scan.h: crowns without roots, a gingiva
// collar, 0.02 mm noise, another triangulation); the scan is displaced by a random rigid motion
// (rotation up to 30 degrees about its centroid, translation up to 20 mm) and registered onto the
// teeth with their roots (what a CT shows) without hands (dental/arch_registration.h). Score: the
// RMS over the scan's vertices of the distance between where the registration put them and where
// they came from. Targets (issue 30): median <= 0.15 mm, worst <= 0.3 mm, no start fails, <= 5 s
// per arch on two cores.
// Two targets: the teeth's own surfaces, and what a CT shows of them (sample/teeth_ct.h: both
// arches voxelised at 0.4 mm with alveolar bone, three amalgam fillings and their streaks, noise;
// the surface where the grey value crosses 1500 HU, the segmentation's teeth threshold), both
// arches in one surface as in a patient's CT.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/json.h"

namespace maxillo::bench {

struct DentalBenchOptions {
  int starts = 20;  // random starts per arch
  unsigned seed = 1;
  // The folder with upper_teeth_merged.stl, lower_teeth_merged.stl, maxilla/ and mandible/ (one
  // STL per tooth); empty: the shared data's openfulljaw-p26-teeth.
  std::filesystem::path data;
};

// One start and where the registration took the scan.
struct DentalTrial {
  double start_mm = 0;            // RMS displacement of the scan's vertices at the start
  double error_mm = 0;            // from the truth, after registration
  double on_teeth_share = 0;      // of the scan within 0.5 mm of the teeth
  double rms_mm = 0, p95_mm = 0;  // distances of those
  double confidence = 0;
  double seconds = 0;
  std::string failure;  // the registration's error, empty when it registered
};

struct DentalArchBench {
  std::string arch;    // "upper" or "lower"
  std::string target;  // "teeth" (their own surfaces) or "CT" (the CT's teeth surface)
  int64_t scan_vertices = 0, teeth_vertices = 0;
  std::vector<DentalTrial> trials;
};

struct DentalBenchmark {
  std::string skipped;  // why it did not run (the teeth are absent); empty when it ran
  unsigned seed = 1;
  double ct_seconds = 0;         // making the CT of the teeth and its teeth surface
  int64_t ct_surface_faces = 0;  // of that surface
  std::vector<DentalArchBench> arches;
};

DentalBenchmark run_dental_benchmark(const DentalBenchOptions& options);

// Per arch and target: starts, failures, error_mm and seconds (median, p90, max), starts within 0.15 mm,
// on_teeth_share, rms_mm and confidence (median); the vertex counts; the seed; the CT's seconds
// and surface faces.
Json dental_benchmark_json(const DentalBenchmark& benchmark);

// As `bench dental` prints it: a line per start, then each arch's figures; or the reason it was skipped.
std::string dental_benchmark_text(const DentalBenchmark& benchmark);

}  // namespace maxillo::bench
