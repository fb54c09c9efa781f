#pragma once
// `maxillo bench register`: rigid registration on the real cadaver head (the shared data's
// cthead-stanford). The moving CT is the head moved by a known rigid transform
// (known_rigid_move, trilinear resampling); each run registers it back with ours
// (imaging/rigid_registration.h, default cranial box) and, in the same run, with elastix when it
// is on PATH (same box as its fixed mask). Seconds and the RMS error over the skin vertices of
// each method per run, the medians and the ratio elastix / ours of the median times. The pieces
// (the head, the move, the error, elastix) are registration_benchmark.h.
// Target (issue 7): RMS <= 0.05 mm and faster than elastix (anchor: elastix 6.3 s, 0.012 mm).
#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/json.h"
#include "imaging/rigid_registration.h"

namespace maxillo::bench {

struct RegisterBenchOptions {
  // The folder holding slices/CThead.*; empty: the shared data's cthead-stanford.
  std::filesystem::path data;
  int runs = 3;  // medians are reported
  // The known move.
  double rotation_deg = 4, translation_mm = 7;
  bool elastix = true;  // also elastix, when it is on PATH
  // Every run with seed 1: the runs' spread is then the non-determinism.
  bool same_seed = false;
  // Ours: the library's defaults unless tuned.
  RigidRegistrationOptions ours;
};

// One method's runs: seconds, and the RMS error over the skin (mm).
struct MethodRuns {
  std::vector<double> seconds, rms_mm;
};

struct RegisterBenchmark {
  std::string skipped;            // why it did not run (the head is absent); empty when it ran
  RegisterBenchOptions options;   // what it ran with
  Eigen::Vector3i size{0, 0, 0};  // the CT's voxels
  RegistrationBox box;            // the cranial box, LPS mm
  int64_t skin_vertices = 0;
  MethodRuns ours;
  std::vector<int> iterations;        // ours, per run
  std::optional<MethodRuns> elastix;  // when elastix ran
  // How far apart ours' runs' answers lie: the largest rotation between run 1's and another's
  // (degrees), and the largest RMS distance over the skin between where they put it (mm).
  double spread_deg = 0, spread_mm = 0;
};

// Skipped (with the reason) when the head's slices are not in the data folder.
RegisterBenchmark run_register_benchmark(const RegisterBenchOptions& options);

// The figures of a run that was not skipped: runs, rotation_deg, translation_mm, skin_vertices,
// ours (seconds, rms_mm per run, median_seconds, median_rms_mm), iterations, threads,
// same_seed, spread_deg, spread_mm; with elastix also elastix (as ours) and
// elastix_to_ours_time_ratio.
Json register_benchmark_json(const RegisterBenchmark& benchmark);

// As `bench register` prints it: the head, a line per run, the medians; or the reason it was
// skipped.
std::string register_benchmark_text(const RegisterBenchmark& benchmark);

}  // namespace maxillo::bench
