// maxillo occlude autorotate UPPER LOWER --hinge x,y,z,x,y,z --pogonion x,y,z [--upper-pose POSE.json]
// [--max-deg 30] [--out FILE.json]: mandibular autorotation. The lower arch (with the mandible)
// turns about the condylar hinge axis through the two --hinge points (lower file coordinates,
// e.g. the condyles) until it first touches the upper arch (placed by POSE's upper_transform,
// e.g. DIR/occlusion.json after a planned impaction); reports the angle (degrees, to 0.01) and how
// far pogonion moved (mm). FILE.json gets the lower arch's 4x4 lower_transform and the figures.
#include <cstdio>
#include <iostream>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json.h"
#include "mesh/mesh_io.h"
#include "occlusion/arch_repair.h"
#include "occlusion/mandibular_autorotation.h"
#include "occlusion/occlusion_files.h"

namespace maxillo::cli {
namespace {

using namespace maxillo::occlusion;

struct AutorotateOptions {
  std::filesystem::path upper, lower, upper_pose, out;
  std::vector<double> hinge, pogonion;
  AutorotationOptions rotation;
};

Eigen::Vector3d point(const std::vector<double>& values, size_t first) {
  return {values[first], values[first + 1], values[first + 2]};
}

int run_autorotate(const AutorotateOptions& options, const GlobalOptions& global) {
  TriangleMesh upper = read_mesh(options.upper), lower = read_mesh(options.lower);
  repair_arch(upper), repair_arch(lower);
  const Eigen::Isometry3d upper_pose =
      options.upper_pose.empty() ? Eigen::Isometry3d::Identity() : read_upper_transform(options.upper_pose);
  const HingeAxis hinge{point(options.hinge, 0), point(options.hinge, 3)};
  if ((hinge.second - hinge.first).norm() < 1e-6)
    throw Error(ErrorCode::kBadValue, "--hinge", "the two hinge points coincide");
  const Eigen::Vector3d pogonion = point(options.pogonion, 0);
  const DistanceField upper_field(upper), lower_field(lower);
  const AutorotationResult r =
      autorotate_mandible(upper_field, lower_field, upper_pose, hinge, pogonion, options.rotation);
  const std::string outcome = r.already_in_contact ? "already_in_contact" : r.contact ? "contact" : "no_contact";
  const Json result{{"outcome", outcome},
                    {"angle_deg", r.angle_deg},
                    {"pogonion_mm", r.pogonion_mm},
                    {"pogonion_displacement_mm",
                     {r.pogonion_displacement.x(), r.pogonion_displacement.y(), r.pogonion_displacement.z()}},
                    {"tolerance_deg", options.rotation.tolerance_deg},
                    {"frame", "lower file coordinates (mm); lower_transform moves the lower arch"},
                    {"lower_transform", transform_to_json(r.lower_motion)}};
  if (!options.out.empty()) write_file_atomically(options.out, result.dump(2) + "\n");
  if (global.json) {
    std::cout << result.dump(2) << "\n";
    return 0;
  }
  if (r.already_in_contact)
    std::printf("the arches already touch: no autorotation\n");
  else if (!r.contact)
    std::printf("no contact within %.1f degrees of closing\n", options.rotation.max_angle_deg);
  else
    std::printf("first contact after %.2f degrees of closing about the hinge axis\n", r.angle_deg);
  std::printf("pogonion moved %.2f mm (%.2f, %.2f, %.2f)\n", r.pogonion_mm, r.pogonion_displacement.x(),
              r.pogonion_displacement.y(), r.pogonion_displacement.z());
  if (!options.out.empty()) std::printf("wrote %s\n", options.out.string().c_str());
  return 0;
}

}  // namespace

void attach_occlude_autorotate(CLI::App& occlude, CommandContext& ctx) {
  CLI::App* app =
      occlude.add_subcommand("autorotate", "close the mandible about the condylar hinge axis until first contact");
  auto options = std::make_shared<AutorotateOptions>();
  app->add_option("UPPER", options->upper, "upper arch mesh (fixed)")->required()->check(CLI::ExistingFile);
  app->add_option("LOWER", options->lower, "lower arch mesh (rotates; its coordinates are the frame)")
      ->required()
      ->check(CLI::ExistingFile);
  app->add_option("--hinge", options->hinge, "two points of the condylar axis x,y,z,x,y,z (mm, lower frame)")
      ->required()
      ->delimiter(',')
      ->expected(6)
      ->check(kCoordinateMm);
  app->add_option("--pogonion", options->pogonion, "pogonion x,y,z (mm, lower frame)")
      ->required()
      ->delimiter(',')
      ->expected(3)
      ->check(kCoordinateMm);
  app->add_option("--upper-pose", options->upper_pose, "JSON with upper_transform placing the upper arch")
      ->check(CLI::ExistingFile);
  app->add_option("--max-deg", options->rotation.max_angle_deg, "largest closing rotation tried")
      ->check(CLI::Range(0.1, 90.0))
      ->capture_default_str();
  app->add_option("--out", options->out, "write the result as JSON");
  app->callback([options, &ctx] { ctx.exit_code = run_autorotate(*options, ctx.global); });
}

}  // namespace maxillo::cli
