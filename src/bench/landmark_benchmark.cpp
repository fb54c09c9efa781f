#include "bench/landmark_benchmark.h"

#include <cstdio>

#include "bench/formatted.h"
#include "bench/peak_memory.h"
#include "bench/timing.h"
#include "core/error.h"
#include "landmarking/landmark_detection.h"
#include "landmarking/landmark_template.h"
#include "sample/phantom_variation.h"
#include "validation/distance_statistics.h"

namespace maxillo::bench {
namespace {

using validation::percentile;

// The spacing of patient `index` when none is given: spread evenly over the flavour's range in
// an order that does not follow the index (so that CT and cone-beam both cover their range).
double drawn_spacing(int index, bool cone_beam) {
  const double share = double((index * 7) % 11) / 10;
  return cone_beam ? 0.3 + 0.2 * share : 0.5 + 1.0 * share;
}

std::string patient_id(const LandmarkBenchOptions& options, int index) {
  char number[16];
  std::snprintf(number, sizeof number, "%03d", index + 1);
  return options.id_prefix + number;
}

// Why a landmark was flagged: the names of its failed checks ("second start", "mirror", ...), or
// its weak evidence.
std::string flag_reasons(const landmarking::DetectedLandmark& l) {
  std::string reasons;
  for (const auto& c : l.checks)
    if (!c.passed) reasons += (reasons.empty() ? "" : ", ") + c.name;
  return reasons.empty() ? "weak evidence" : reasons;
}

ScanRun run_one(const LandmarkBenchOptions& options, int index) {
  ScanRun run;
  run.patient_id = patient_id(options, index);
  run.cone_beam = options.cone_beam_every > 0 && (index + 1) % options.cone_beam_every == 0;
  run.spacing_mm = options.spacing_mm.value_or(drawn_spacing(index, run.cone_beam));
  const PhantomSpec spec =
      varied_phantom_spec(run.patient_id, run.cone_beam ? ScannerKind::kConeBeam : ScannerKind::kCt, run.spacing_mm);
  run.variation = describe_variation(spec);
  Phantom phantom = make_phantom(spec);
  phantom.labels = {};  // the detector gets the scan alone
  run.voxels = phantom.ct.geometry.voxel_count();
  for (const std::string& label : landmarking::detected_labels())
    run.landmarks[label].has_truth = find_landmark(phantom.landmarks, label).has_value();

  reset_resident_peak();
  const auto start = Clock::now();
  try {
    const landmarking::LandmarkDetection found = landmarking::detect_landmarks(phantom.ct, run.patient_id);
    run.seconds = seconds_since(start);
    for (const auto& l : found.landmarks) {
      LandmarkOutcome& outcome = run.landmarks[l.label];
      outcome.detected = l.position.has_value();
      outcome.flagged = l.flagged();
      if (outcome.flagged) outcome.flagged_for = flag_reasons(l);
      if (outcome.detected && outcome.has_truth)
        outcome.error_mm = (*l.position - *find_landmark(phantom.landmarks, l.label)).norm();
    }
  } catch (const Error& error) {
    run.seconds = seconds_since(start);
    run.error = error.what();
  }
  run.peak_kb = resident_peak_kb();
  return run;
}

struct LandmarkFigures {
  std::vector<double> errors;
  std::vector<double> unflagged_errors;  // what a planner uses without a person's confirmation
  int missed = 0, flagged = 0, invented = 0, absent_right = 0;
};

std::map<std::string, LandmarkFigures> per_landmark(const std::vector<ScanRun>& runs) {
  std::map<std::string, LandmarkFigures> figures;
  for (const ScanRun& run : runs)
    for (const auto& [label, o] : run.landmarks) {
      LandmarkFigures& f = figures[label];
      if (o.has_truth && o.detected) f.errors.push_back(o.error_mm);
      if (o.has_truth && o.detected && !o.flagged) f.unflagged_errors.push_back(o.error_mm);
      f.missed += o.has_truth && !o.detected;
      f.invented += !o.has_truth && o.detected;
      f.absent_right += !o.has_truth && !o.detected;
      f.flagged += o.detected && o.flagged;
    }
  return figures;
}

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? 0 : sum / double(values.size());
}

double share_within(const std::vector<double>& values, double limit) {
  int within = 0;
  for (double v : values) within += v <= limit;
  return values.empty() ? 0 : double(within) / double(values.size());
}

// "    over 2 mm: B 27.1, Pog 21.6" / "    missed: U1" / "    flagged: L1 (second start)" lines
// (each left out when empty).
std::string worst_and_missed(const ScanRun& run) {
  std::string over, missed, flagged;
  for (const auto& [label, o] : run.landmarks) {
    if (o.has_truth && o.detected && o.error_mm > 2) over += formatted(" %s %.1f", label.c_str(), o.error_mm);
    if (o.has_truth && !o.detected) missed += " " + label;
    if (!o.has_truth && o.detected) missed += " (" + label + " invented)";
    if (o.flagged) flagged += " " + label + " (" + o.flagged_for + ")";
  }
  std::string text;
  if (!over.empty()) text += "    over 2 mm:" + over + "\n";
  if (!missed.empty()) text += "    missed:" + missed + "\n";
  if (!flagged.empty()) text += "    flagged:" + flagged + "\n";
  return text;
}

// Each landmark of one scan: found or not, its error where it has a truth, flagged and why.
Json scan_landmarks_json(const ScanRun& run) {
  Json landmarks = Json::object();
  for (const auto& [label, o] : run.landmarks) {
    Json entry = {{"has_truth", o.has_truth}, {"detected", o.detected}, {"flagged", o.flagged}};
    if (o.has_truth && o.detected) entry["error_mm"] = o.error_mm;
    if (o.flagged) entry["flagged_for"] = o.flagged_for;
    landmarks[label] = entry;
  }
  return landmarks;
}

}  // namespace

std::vector<ScanRun> run_landmark_benchmark(const LandmarkBenchOptions& options) {
  std::vector<ScanRun> runs;
  for (int index = 0; index < options.patients; ++index) runs.push_back(run_one(options, index));
  return runs;
}

Json landmark_benchmark_json(const std::vector<ScanRun>& runs) {
  Json scans = Json::array(), landmarks = Json::object();
  std::vector<double> all_errors, seconds, peaks;
  for (const ScanRun& run : runs) {
    scans.push_back({{"patient_id", run.patient_id},
                     {"cone_beam", run.cone_beam},
                     {"spacing_mm", run.spacing_mm},
                     {"voxels", run.voxels},
                     {"variation", run.variation},
                     {"error", run.error},
                     {"seconds", run.seconds},
                     {"peak_mb", double(run.peak_kb) / 1024},
                     {"landmarks", scan_landmarks_json(run)}});
    seconds.push_back(run.seconds);
    peaks.push_back(double(run.peak_kb) / 1024);
  }
  for (const auto& [label, f] : per_landmark(runs)) {
    all_errors.insert(all_errors.end(), f.errors.begin(), f.errors.end());
    landmarks[label] = {{"found", f.errors.size()},
                        {"mean_mm", mean(f.errors)},
                        {"p95_mm", f.errors.empty() ? 0 : percentile(f.errors, 95)},
                        {"unflagged", f.unflagged_errors.size()},
                        {"p95_unflagged_mm", f.unflagged_errors.empty() ? 0 : percentile(f.unflagged_errors, 95)},
                        {"within_2_mm", share_within(f.errors, 2)},
                        {"missed", f.missed},
                        {"flagged", f.flagged},
                        {"invented", f.invented},
                        {"absent_as_it_should", f.absent_right}};
  }
  return {{"scans", scans},
          {"landmarks", landmarks},
          {"mean_mm", mean(all_errors)},
          {"within_2_mm", share_within(all_errors, 2)},
          {"seconds_median", seconds.empty() ? 0 : median(seconds)},
          {"peak_mb_max", peaks.empty() ? 0 : percentile(peaks, 100)}};
}

std::string landmark_benchmark_text(const std::vector<ScanRun>& runs) {
  std::string text;
  for (const ScanRun& run : runs) {
    text += formatted("%s %s %.2f mm, %lld voxels: %s %.1f s, peak %.0f MB\n", run.patient_id.c_str(),
                      run.cone_beam ? "cone-beam" : "CT", run.spacing_mm, run.voxels,
                      run.error.empty() ? "detected in" : "FAILED after", run.seconds, double(run.peak_kb) / 1024);
    text += "    " + run.variation + "\n";
    if (!run.error.empty()) text += "    " + run.error + "\n";
    text += worst_and_missed(run);
  }
  text += formatted("\n%-5s %5s %8s %8s %7s %6s %7s %8s %6s %14s\n", "label", "found", "mean mm", "P95 mm", "<=2 mm",
                    "missed", "flagged", "invented", "absent", "unflagged P95");
  std::vector<double> all_errors;
  for (const auto& [label, f] : per_landmark(runs)) {
    all_errors.insert(all_errors.end(), f.errors.begin(), f.errors.end());
    const std::string unflagged =
        f.unflagged_errors.empty()
            ? "-"
            : formatted("%.2f (%zu)", percentile(f.unflagged_errors, 95), f.unflagged_errors.size());
    text +=
        formatted("%-5s %5zu %8.2f %8.2f %6.0f%% %6d %7d %8d %6d %14s\n", label.c_str(), f.errors.size(),
                  mean(f.errors), f.errors.empty() ? 0.0 : percentile(f.errors, 95), 100 * share_within(f.errors, 2),
                  f.missed, f.flagged, f.invented, f.absent_right, unflagged.c_str());
  }
  const Json figures = landmark_benchmark_json(runs);
  text += formatted(
      "all: mean %.2f mm over %zu detections, %.0f%% within 2 mm (targets: mean <= 1.0 mm, every P95 <= 2.0 mm)\n",
      mean(all_errors), all_errors.size(), 100 * share_within(all_errors, 2));
  text += formatted("per scan: median %.1f s, largest resident peak %.0f MB\n", figures["seconds_median"].get<double>(),
                    figures["peak_mb_max"].get<double>());
  return text;
}

}  // namespace maxillo::bench
