#pragma once
// `maxillo bench landmarks`: the automatic landmarks (landmarking/landmark_detection.h) against
// the truth of many different phantoms. Each patient is drawn from its Patient ID
// (sample/phantom_variation.h: size, jaws, pose, noise; every third one a cone-beam scan with
// grey values that are not HU, cupping, metal streaks and a cut field) at a spacing drawn from
// the ID too (CT 0.5-1.5 mm, cone-beam 0.3-0.5 mm) unless one is given. The truth is what the
// generator placed, moved with the head; a landmark outside a cone-beam field has none and must
// come back absent.
//
// Per landmark: the radial error of every detection (flagged ones included: a person sees them,
// but they count), its mean and P95, the share within 2 mm, and how many were missed (truth, no
// detection), flagged, or invented (a detection with no truth); beside them the P95 of the
// unflagged detections alone, those a plan uses without a person's confirmation. Per scan: the detection's wall
// time and the process's resident peak while it ran (the scan's own voxels included), with the
// voxel count; in the JSON each landmark's outcome per scan as well. Targets (issue 28): mean <= 1.0 mm, every landmark's P95 <= 2.0 mm, <= 20 s and
// <= 1.5 GB per 512 x 512 x 330 scan on two cores.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/json.h"

namespace maxillo::bench {

struct LandmarkBenchOptions {
  int patients = 30;
  int cone_beam_every = 3;           // every n-th patient is a cone-beam scan (0: none)
  std::optional<double> spacing_mm;  // one spacing for all; default: drawn per patient
  std::string id_prefix = "BENCH-";  // Patient IDs: prefix + 001, 002, ...
};

// One landmark of one scan.
struct LandmarkOutcome {
  bool has_truth = false, detected = false, flagged = false;
  double error_mm = 0;      // when both
  std::string flagged_for;  // the failed checks' names, or "weak evidence"
};

struct ScanRun {
  std::string patient_id, variation, error;  // error: why the detection stopped (empty: it ran)
  bool cone_beam = false;
  double spacing_mm = 0;
  long long voxels = 0;
  double seconds = 0;  // detection, wall time
  long peak_kb = 0;    // resident peak while detecting
  std::map<std::string, LandmarkOutcome> landmarks;
};

std::vector<ScanRun> run_landmark_benchmark(const LandmarkBenchOptions& options);
Json landmark_benchmark_json(const std::vector<ScanRun>& runs);
std::string landmark_benchmark_text(const std::vector<ScanRun>& runs);

}  // namespace maxillo::bench
