#include "bench/occlusion_benchmark.h"

#include <random>

#include "bench/formatted.h"
#include "bench/shared_data.h"
#include "bench/timing.h"
#include "core/error.h"
#include "mesh/mesh_io.h"
#include "occlusion/arch_repair.h"
#include "occlusion/occlusion_benchmark.h"
#include "occlusion/occlusion_comparison.h"

namespace maxillo::bench {
namespace {

using namespace maxillo::occlusion;

// The arches as scanned: the pose every start is displaced from and every result scored against.
const Eigen::Isometry3d kNaturalPose = Eigen::Isometry3d::Identity();

// What the alignment of every pose works with: the arches, the springs between the natural
// occlusion's contacts, and the occlusal region scored.
struct NaturalOcclusion {
  const TriangleMesh& upper;
  const DistanceField &upper_field, &lower_field;
  std::vector<SpringPair> springs;
  std::vector<int> region;
};

PoseResult align_pose(const NaturalOcclusion& natural, const Eigen::Isometry3d& start) {
  const auto clock = Clock::now();
  MotionEngine engine(natural.upper_field, natural.lower_field, start);
  const AlignmentResult aligned = align_guided(engine, natural.springs);
  PoseResult r;
  r.seconds = seconds_since(clock);
  r.p95_mm = compare_poses(natural.upper, natural.region, kNaturalPose, aligned.pose).statistics.p95_mm;
  r.start_p95_mm = compare_poses(natural.upper, natural.region, kNaturalPose, start).statistics.p95_mm;
  r.penetration_mm = aligned.penetration_mm;
  r.allowed_mm = engine.allowed_penetration_mm();
  r.iterations = aligned.iterations;
  r.converged = aligned.status == AlignmentStatus::Converged;
  return r;
}

Json spread(const std::vector<double>& values) {
  return {{"median", percentile(values, 50)}, {"p90", percentile(values, 90)}, {"max", percentile(values, 100)}};
}

std::string pose_line(int number, const PoseResult& r) {
  return formatted(
      "pose %3d: start P95 %.2f mm -> P95 %.3f mm, %3d iterations%s, penetration %.3f mm (allowed %.3f), %.2f s\n",
      number, r.start_p95_mm, r.p95_mm, r.iterations, r.converged ? "" : " (limit)", r.penetration_mm, r.allowed_mm,
      r.seconds);
}

}  // namespace

OcclusionBenchmark run_occlusion_benchmark(const OcclusionBenchOptions& options) {
  OcclusionBenchmark result;
  result.seed = options.seed;
  const RealTeeth teeth = real_teeth(options.data);
  if (!teeth.absent.empty()) {
    result.skipped = teeth.absent;
    return result;
  }
  TriangleMesh upper = read_mesh(teeth.upper), lower = read_mesh(teeth.lower);
  repair_arch(upper), repair_arch(lower);
  const auto build_clock = Clock::now();
  const DistanceField upper_field(upper), lower_field(lower);
  result.distance_fields_seconds = seconds_since(build_clock);
  result.natural_penetration_mm = assess_contacts(upper_field, lower_field, kNaturalPose, 2.0).max_penetration_mm;
  const NaturalOcclusion natural{upper, upper_field, lower_field,
                                 contact_spring_pairs(upper_field, lower_field, kNaturalPose, 4, 0.1),
                                 occlusal_region(upper_field, lower_field, kNaturalPose, 3.0)};
  if (natural.springs.size() < 4)
    throw Error(ErrorCode::kProcessing, teeth.upper.string(), "fewer than 4 contacts in the natural occlusion");
  result.upper_vertices = upper.vertex_count(), result.lower_vertices = lower.vertex_count();
  result.region_vertices = natural.region.size();

  const Eigen::Vector3d centre = upper.vertices.colwise().mean().transpose();
  std::mt19937 rng(options.seed);
  for (int k = 0; k < options.poses; ++k) {
    const Eigen::Isometry3d start =
        place_in_contact(upper_field, lower_field, random_displacement(rng, centre, 3.0, 5.0) * kNaturalPose,
                         result.natural_penetration_mm);
    result.poses.push_back(align_pose(natural, start));
  }
  return result;
}

Json occlusion_benchmark_json(const OcclusionBenchmark& benchmark) {
  std::vector<double> p95s, seconds;
  int passing = 0, violations = 0;
  for (const PoseResult& r : benchmark.poses) {
    p95s.push_back(r.p95_mm), seconds.push_back(r.seconds);
    passing += r.p95_mm <= 0.3;
    violations += r.penetration_mm > r.allowed_mm + 1e-9;
  }
  return {{"poses", benchmark.poses.size()},
          {"seed", benchmark.seed},
          {"upper_vertices", benchmark.upper_vertices},
          {"lower_vertices", benchmark.lower_vertices},
          {"occlusal_region_vertices", benchmark.region_vertices},
          {"natural_penetration_mm", benchmark.natural_penetration_mm},
          {"distance_fields_seconds", benchmark.distance_fields_seconds},
          {"p95_mm", spread(p95s)},
          {"poses_within_0_3_mm", passing},
          {"penetration_limit_violations", violations},
          {"seconds", spread(seconds)}};
}

std::string occlusion_benchmark_text(const OcclusionBenchmark& benchmark) {
  if (!benchmark.skipped.empty()) return "skipped: " + benchmark.skipped + "\n";
  std::string text;
  for (size_t k = 0; k < benchmark.poses.size(); ++k) text += pose_line(int(k + 1), benchmark.poses[k]);
  const Json figures = occlusion_benchmark_json(benchmark);
  const Json &p95 = figures["p95_mm"], &seconds = figures["seconds"];
  text += formatted("arches: %lld + %lld vertices, occlusal region %zu vertices, natural penetration %.3f mm\n",
                    (long long)benchmark.upper_vertices, (long long)benchmark.lower_vertices, benchmark.region_vertices,
                    benchmark.natural_penetration_mm);
  text +=
      formatted("distance fields (BVH + pseudo-normals, once per arch): %.2f s\n", benchmark.distance_fields_seconds);
  text += formatted(
      "P95 over the occlusal region: median %.3f mm, P90 %.3f mm, max %.3f mm; %d of %d poses <= 0.3 mm (target: "
      "all)\n",
      p95["median"].get<double>(), p95["p90"].get<double>(), p95["max"].get<double>(),
      figures["poses_within_0_3_mm"].get<int>(), int(benchmark.poses.size()));
  text += formatted("time per pose: median %.2f s, P90 %.2f s, max %.2f s (target: median <= 1 s)\n",
                    seconds["median"].get<double>(), seconds["p90"].get<double>(), seconds["max"].get<double>());
  return text +
         formatted("penetration limit violated in %d poses\n", figures["penetration_limit_violations"].get<int>());
}

}  // namespace maxillo::bench
