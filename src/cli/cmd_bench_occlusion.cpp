// maxillo bench occlusion [--poses 100] [--seed 1] [--data DIR]: guided alignment benchmark on the
// real teeth of openfulljaw-p26-teeth (upper and lower arches scanned in natural occlusion).
// For each pose: the upper arch is displaced by a random rigid motion (rotation up to 5 degrees
// about its centre, translation up to 3 mm), moved along z into contact (penetrating the lower
// arch as deep as the natural occlusion does, which scan noise makes ~0.3 mm: with less, the
// engine's rule "no deeper than the start + 0.05 mm" would forbid the natural occlusion itself),
// then pulled back by 4 springs between points where
// the teeth touch in the natural occlusion. Score: P95 of the displacement between the final
// and the natural pose over the occlusal region (upper vertices within 3 mm of the lower arch).
// Target (issue 6): P95 <= 0.3 mm, median time <= 1 s per pose.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "cli/command.h"
#include "core/error.h"
#include "core/json.h"
#include "mesh/mesh_io.h"
#include "occlusion/arch_repair.h"
#include "occlusion/occlusion_benchmark.h"
#include "occlusion/occlusion_comparison.h"

namespace maxillo::cli {
namespace {

using namespace maxillo::occlusion;

struct OcclusionBenchArguments {
  int poses = 100;
  unsigned seed = 1;
  std::filesystem::path data;
};

std::filesystem::path default_data_folder() {
  const char* shared = std::getenv("MAXILLO_SHARED_DATA");
  return std::filesystem::path(shared ? shared : "../shared/data") / "openfulljaw-p26-teeth";
}

struct PoseResult {
  double p95_mm = 0, seconds = 0, start_p95_mm = 0, penetration_mm = 0, allowed_mm = 0;
  int iterations = 0;
  bool converged = false;
};

void run_occlusion_bench(const OcclusionBenchArguments& args, CommandContext& ctx) {
  const auto folder = args.data.empty() ? default_data_folder() : args.data;
  const auto upper_file = folder / "upper_teeth_merged.stl", lower_file = folder / "lower_teeth_merged.stl";
  if (!std::filesystem::exists(upper_file) || !std::filesystem::exists(lower_file)) {
    std::cout << "skipped: the real teeth are not at " << folder.string()
              << " (set MAXILLO_SHARED_DATA or --data to the folder holding openfulljaw-p26-teeth)\n";
    return;
  }
  TriangleMesh upper = read_mesh(upper_file), lower = read_mesh(lower_file);
  repair_arch(upper), repair_arch(lower);
  const auto build_clock = std::chrono::steady_clock::now();
  const DistanceField upper_field(upper), lower_field(lower);
  const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - build_clock).count();
  const Eigen::Isometry3d natural = Eigen::Isometry3d::Identity();
  const double natural_penetration = assess_contacts(upper_field, lower_field, natural, 2.0).max_penetration_mm;
  const std::vector<SpringPair> springs = contact_spring_pairs(upper_field, lower_field, natural, 4, 0.1);
  const std::vector<int> region = occlusal_region(upper_field, lower_field, natural, 3.0);
  if (springs.size() < 4)
    throw Error(ErrorCode::kProcessing, upper_file.string(), "fewer than 4 contacts in the natural occlusion");
  const Eigen::Vector3d centre = upper.vertices.colwise().mean().transpose();

  std::mt19937 rng(args.seed);
  std::vector<PoseResult> results;
  for (int k = 0; k < args.poses; ++k) {
    const Eigen::Isometry3d start = place_in_contact(
        upper_field, lower_field, random_displacement(rng, centre, 3.0, 5.0) * natural, natural_penetration);
    const auto clock = std::chrono::steady_clock::now();
    MotionEngine engine(upper_field, lower_field, start);
    const AlignmentResult aligned = align_guided(engine, springs);
    PoseResult r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    r.p95_mm = compare_poses(upper, region, natural, aligned.pose).statistics.p95_mm;
    r.start_p95_mm = compare_poses(upper, region, natural, start).statistics.p95_mm;
    r.penetration_mm = aligned.penetration_mm;
    r.allowed_mm = engine.allowed_penetration_mm();
    r.iterations = aligned.iterations;
    r.converged = aligned.status == AlignmentStatus::Converged;
    results.push_back(r);
    if (!ctx.global.json)
      std::printf(
          "pose %3d: start P95 %.2f mm -> P95 %.3f mm, %3d iterations%s, penetration %.3f mm (allowed %.3f), %.2f s\n",
          k + 1, r.start_p95_mm, r.p95_mm, r.iterations, r.converged ? "" : " (limit)", r.penetration_mm, r.allowed_mm,
          r.seconds);
  }
  std::vector<double> p95s, seconds;
  int passing = 0, violations = 0;
  for (const PoseResult& r : results) {
    p95s.push_back(r.p95_mm), seconds.push_back(r.seconds);
    passing += r.p95_mm <= 0.3;
    violations += r.penetration_mm > r.allowed_mm + 1e-9;
  }
  Json summary{
      {"poses", args.poses},
      {"seed", args.seed},
      {"upper_vertices", upper.vertex_count()},
      {"lower_vertices", lower.vertex_count()},
      {"occlusal_region_vertices", region.size()},
      {"natural_penetration_mm", natural_penetration},
      {"distance_fields_seconds", build_seconds},
      {"p95_mm", {{"median", percentile(p95s, 50)}, {"p90", percentile(p95s, 90)}, {"max", percentile(p95s, 100)}}},
      {"poses_within_0_3_mm", passing},
      {"penetration_limit_violations", violations},
      {"seconds",
       {{"median", percentile(seconds, 50)}, {"p90", percentile(seconds, 90)}, {"max", percentile(seconds, 100)}}}};
  if (ctx.global.json) {
    std::cout << summary.dump(2) << "\n";
    return;
  }
  std::printf("arches: %lld + %lld vertices, occlusal region %zu vertices, natural penetration %.3f mm\n",
              (long long)upper.vertex_count(), (long long)lower.vertex_count(), region.size(), natural_penetration);
  std::printf("distance fields (BVH + pseudo-normals, once per arch): %.2f s\n", build_seconds);
  std::printf(
      "P95 over the occlusal region: median %.3f mm, P90 %.3f mm, max %.3f mm; %d of %d poses <= 0.3 mm (target: "
      "all)\n",
      percentile(p95s, 50), percentile(p95s, 90), percentile(p95s, 100), passing, args.poses);
  std::printf("time per pose: median %.2f s, P90 %.2f s, max %.2f s (target: median <= 1 s)\n", percentile(seconds, 50),
              percentile(seconds, 90), percentile(seconds, 100));
  std::printf("penetration limit violated in %d poses\n", violations);
}

}  // namespace

void attach_bench_occlusion(CLI::App& bench, CommandContext& ctx) {
  CLI::App* occlusion =
      bench.add_subcommand("occlusion", "guided occlusion alignment on the real teeth (P95 mm, s/pose)");
  auto args = std::make_shared<OcclusionBenchArguments>();
  occlusion->add_option("--poses", args->poses, "random starting poses")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  occlusion->add_option("--seed", args->seed, "random seed")->capture_default_str();
  occlusion->add_option("--data", args->data,
                        "folder with upper_teeth_merged.stl, lower_teeth_merged.stl "
                        "(default: $MAXILLO_SHARED_DATA or ../shared/data, /openfulljaw-p26-teeth)");
  occlusion->callback([args, &ctx] { run_occlusion_bench(*args, ctx); });
}

}  // namespace maxillo::cli
