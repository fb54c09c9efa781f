// maxillo occlude compare UPPER LOWER POSE_A.json POSE_B.json [--roi-mm 3] [--map FILE.csv]:
// the distance map of the upper arch between two occlusions (thesis ch. 7, Table 1). Both pose
// files hold an upper_transform (START.json or a previous DIR/occlusion.json); POSE_A is the
// reference whose occlusal region (upper vertices within --roi-mm of the lower arch) is compared.
#include <cstdio>
#include <iostream>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/json.h"
#include "mesh/mesh_io.h"
#include "occlusion/arch_repair.h"
#include "occlusion/occlusion_comparison.h"
#include "occlusion/occlusion_files.h"

namespace maxillo::cli {
namespace {

using namespace maxillo::occlusion;

struct CompareOptions {
  std::filesystem::path upper, lower, pose_a, pose_b, map;
  double roi_mm = 3.0;
};

void write_distance_map(const TriangleMesh& upper, const Eigen::Isometry3d& pose_a, const OcclusionComparison& c,
                        const std::filesystem::path& path) {
  std::string text = "vertex,x_mm,y_mm,z_mm,distance_mm\n";
  char line[160];
  for (size_t i = 0; i < c.region.size(); ++i) {
    const Eigen::Vector3d x = pose_a * Eigen::Vector3d(upper.vertices.row(c.region[i]).transpose());
    std::snprintf(line, sizeof line, "%d,%.4f,%.4f,%.4f,%.4f\n", c.region[i], x.x(), x.y(), x.z(), c.distance_mm[i]);
    text += line;
  }
  write_file_atomically(path, text);
}

int run_compare(const CompareOptions& options, const GlobalOptions& global) {
  TriangleMesh upper = read_mesh(options.upper), lower = read_mesh(options.lower);
  repair_arch(upper), repair_arch(lower);
  const Eigen::Isometry3d pose_a = read_upper_transform(options.pose_a), pose_b = read_upper_transform(options.pose_b);
  const DistanceField upper_field(upper), lower_field(lower);
  const OcclusionComparison c = compare_occlusions(upper_field, lower_field, pose_a, pose_b, options.roi_mm);
  if (!options.map.empty()) write_distance_map(upper, pose_a, c, options.map);
  const DistanceStatistics& s = c.statistics;
  if (global.json) {
    std::cout << Json{{"roi_mm", options.roi_mm}, {"region_vertices", s.count}, {"median_mm", s.median_mm},
                      {"p90_mm", s.p90_mm},       {"p95_mm", s.p95_mm},         {"max_mm", s.max_mm}}
                     .dump(2)
              << "\n";
  } else {
    std::printf("occlusal region: %d upper vertices within %.2f mm of the lower arch at pose A\n", s.count,
                options.roi_mm);
    std::printf("distance between the poses: median %.3f mm, P90 %.3f mm, P95 %.3f mm, max %.3f mm\n", s.median_mm,
                s.p90_mm, s.p95_mm, s.max_mm);
    if (!options.map.empty()) std::printf("wrote %s\n", options.map.string().c_str());
  }
  return 0;
}

}  // namespace

void attach_occlude_compare(CLI::App& occlude, CommandContext& ctx) {
  CLI::App* compare =
      occlude.add_subcommand("compare", "distance map of the upper arch between two poses (median, P90, P95)");
  auto options = std::make_shared<CompareOptions>();
  compare->add_option("UPPER", options->upper, "upper arch mesh")->required()->check(CLI::ExistingFile);
  compare->add_option("LOWER", options->lower, "lower arch mesh (its coordinates are the frame)")
      ->required()
      ->check(CLI::ExistingFile);
  compare->add_option("POSE_A", options->pose_a, "JSON with upper_transform: the reference occlusion")
      ->required()
      ->check(CLI::ExistingFile);
  compare->add_option("POSE_B", options->pose_b, "JSON with upper_transform: the occlusion compared")
      ->required()
      ->check(CLI::ExistingFile);
  compare->add_option("--roi-mm", options->roi_mm, "region of interest: upper vertices this close to the lower arch")
      ->check(CLI::Range(0.1, 50.0))
      ->capture_default_str();
  compare->add_option("--map", options->map, "write the distance map (CSV: vertex, position at pose A, distance)");
  compare->callback([options, &ctx] { ctx.exit_code = run_compare(*options, ctx.global); });
}

}  // namespace maxillo::cli
