#include "bench/dental_benchmark.h"

#include <random>

#include "bench/formatted.h"
#include "bench/shared_data.h"
#include "bench/timing.h"
#include "core/error.h"
#include "dental/arch_registration.h"
#include "geometry/mesh_transform.h"
#include "imaging/segmentation.h"
#include "mesh/mesh_io.h"
#include "mesh/surface_extraction.h"
#include "occlusion/occlusion_benchmark.h"
#include "sample/simulated_dental_scan.h"
#include "sample/teeth_ct.h"

namespace maxillo::bench {
namespace {

constexpr double kMaxStartMm = 20, kMaxStartDeg = 30;
// Where the CT's teeth begin: the segmentation's teeth threshold (imaging/segmentation.h).
const double kTeethHu = SegmentationOptions{}.teeth_hu;

DentalTrial register_from(const TriangleMesh& scan, const TriangleMesh& teeth, const Eigen::Isometry3d& start) {
  DentalTrial trial;
  const TriangleMesh displaced = transformed(scan, start);
  const Eigen::Isometry3d truth = start.inverse();
  trial.start_mm = dental::pose_distance_mm(displaced, Eigen::Isometry3d::Identity(), truth);
  const auto clock = Clock::now();
  try {
    const dental::ArchRegistration r = dental::register_arch(displaced, teeth);
    trial.seconds = seconds_since(clock);
    trial.error_mm = dental::pose_distance_mm(displaced, r.fit.transform, truth);
    trial.on_teeth_share = r.fit.on_teeth_share;
    trial.rms_mm = r.fit.rms_mm;
    trial.p95_mm = r.fit.p95_mm;
    trial.confidence = r.confidence;
  } catch (const Error& e) {
    trial.seconds = seconds_since(clock);
    trial.failure = e.what();
  }
  return trial;
}

DentalArchBench bench_arch(const std::string& name, const std::string& target, const TriangleMesh& scan,
                           const TriangleMesh& teeth, int starts, std::mt19937& random) {
  DentalArchBench arch{name, target, scan.vertex_count(), teeth.vertex_count(), {}};
  const Eigen::Vector3d centre = scan.vertices.colwise().mean().transpose();
  for (int k = 0; k < starts; ++k)
    arch.trials.push_back(
        register_from(scan, teeth, occlusion::random_displacement(random, centre, kMaxStartMm, kMaxStartDeg)));
  return arch;
}

Json spread(const std::vector<double>& values) {
  return {{"median", occlusion::percentile(values, 50)},
          {"p90", occlusion::percentile(values, 90)},
          {"max", occlusion::percentile(values, 100)}};
}

Json arch_json(const DentalArchBench& arch) {
  std::vector<double> errors, seconds, shares, rms, confidence;
  int failures = 0, within = 0;
  for (const auto& t : arch.trials) {
    seconds.push_back(t.seconds);
    if (!t.failure.empty()) {
      ++failures;
      continue;
    }
    errors.push_back(t.error_mm), shares.push_back(t.on_teeth_share), rms.push_back(t.rms_mm);
    confidence.push_back(t.confidence);
    within += t.error_mm <= 0.15;
  }
  return {{"arch", arch.arch},
          {"target", arch.target},
          {"starts", arch.trials.size()},
          {"failures", failures},
          {"scan_vertices", arch.scan_vertices},
          {"teeth_vertices", arch.teeth_vertices},
          {"error_mm", spread(errors)},
          {"starts_within_0_15_mm", within},
          {"on_teeth_share_median", occlusion::percentile(shares, 50)},
          {"rms_mm_median", occlusion::percentile(rms, 50)},
          {"confidence_median", occlusion::percentile(confidence, 50)},
          {"seconds", spread(seconds)}};
}

}  // namespace

DentalBenchmark run_dental_benchmark(const DentalBenchOptions& options) {
  DentalBenchmark result;
  result.seed = options.seed;
  const RealTeeth teeth = real_teeth(options.data);
  if (!teeth.absent.empty()) {
    result.skipped = teeth.absent;
    return result;
  }
  const TriangleMesh upper = read_mesh(teeth.upper), lower = read_mesh(teeth.lower);
  const Eigen::Vector3d between = 0.5 * (upper.vertices.colwise().mean() + lower.vertices.colwise().mean()).transpose();
  DentalScanOptions scan_options;
  scan_options.seed = options.seed;
  const TriangleMesh upper_scan =
      simulated_dental_scan(read_meshes_in(teeth.folder / "maxilla"), between, scan_options);
  const TriangleMesh lower_scan =
      simulated_dental_scan(read_meshes_in(teeth.folder / "mandible"), between, scan_options);
  std::mt19937 random(options.seed);
  result.arches.push_back(bench_arch("upper", "teeth", upper_scan, upper, options.starts, random));
  result.arches.push_back(bench_arch("lower", "teeth", lower_scan, lower, options.starts, random));
  const auto clock = Clock::now();
  SurfaceOptions surface;
  surface.keep_largest_components = 0;  // every tooth is a piece of its own
  TeethCtOptions ct_options;
  ct_options.seed = options.seed;
  const TriangleMesh ct_teeth = extract_surface(teeth_ct(upper, lower, ct_options), kTeethHu, surface);
  result.ct_seconds = seconds_since(clock);
  result.ct_surface_faces = ct_teeth.face_count();
  result.arches.push_back(bench_arch("upper", "CT", upper_scan, ct_teeth, options.starts, random));
  result.arches.push_back(bench_arch("lower", "CT", lower_scan, ct_teeth, options.starts, random));
  return result;
}

Json dental_benchmark_json(const DentalBenchmark& benchmark) {
  Json arches = Json::array();
  for (const auto& arch : benchmark.arches) arches.push_back(arch_json(arch));
  return {{"seed", benchmark.seed},
          {"max_start_mm", kMaxStartMm},
          {"max_start_deg", kMaxStartDeg},
          {"ct_seconds", benchmark.ct_seconds},
          {"ct_surface_faces", benchmark.ct_surface_faces},
          {"arches", arches}};
}

std::string dental_benchmark_text(const DentalBenchmark& benchmark) {
  if (!benchmark.skipped.empty()) return "skipped: " + benchmark.skipped + "\n";
  std::string text;
  for (const auto& arch : benchmark.arches) {
    for (size_t k = 0; k < arch.trials.size(); ++k) {
      const DentalTrial& t = arch.trials[k];
      text += t.failure.empty()
                  ? formatted(
                        "%s onto %s, start %2zu: %5.1f mm off -> %.3f mm from the truth; %.0f %% on the teeth, RMS "
                        "%.3f mm, P95 %.3f mm, confidence %.2f, %.2f s\n",
                        arch.arch.c_str(), arch.target.c_str(), k + 1, t.start_mm, t.error_mm, 100 * t.on_teeth_share,
                        t.rms_mm, t.p95_mm, t.confidence, t.seconds)
                  : formatted("%s onto %s, start %2zu: %5.1f mm off -> FAILED: %s\n", arch.arch.c_str(),
                              arch.target.c_str(), k + 1, t.start_mm, t.failure.c_str());
    }
  }
  text += formatted("the CT of the teeth (0.4 mm, 3 fillings) and its teeth surface (%lld faces): %.1f s\n",
                    (long long)benchmark.ct_surface_faces, benchmark.ct_seconds);
  for (const auto& arch : benchmark.arches) {
    const Json f = arch_json(arch);
    text += formatted(
        "%s arch onto the %s: scan %lld vertices onto %lld; from the truth median %.3f mm, P90 %.3f, worst %.3f "
        "(targets 0.15, 0.3); %d of %d starts within 0.15 mm, %d failed; %.2f s per arch (median; target 5)\n",
        arch.arch.c_str(), arch.target == "CT" ? "CT's teeth surface" : "teeth's own surfaces",
        (long long)arch.scan_vertices, (long long)arch.teeth_vertices, f["error_mm"]["median"].get<double>(),
        f["error_mm"]["p90"].get<double>(), f["error_mm"]["max"].get<double>(), f["starts_within_0_15_mm"].get<int>(),
        int(arch.trials.size()), f["failures"].get<int>(), f["seconds"]["median"].get<double>());
  }
  return text;
}

}  // namespace maxillo::bench
