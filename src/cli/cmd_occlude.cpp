// maxillo occlude UPPER LOWER --pairs PAIRS.csv [--start START.json] --out DIR: virtual occlusion
// (thesis ch. 7). Reads both arches (STL/PLY/OBJ/VTP; the lower arch fixes the frame), repairs
// shell orientation, places the upper arch by START's upper_transform, pulls it towards the
// lower arch with the point pairs as springs while contacts stop it (guided alignment), and
// writes DIR/occlusion.json (final 4x4 upper_transform relative to the input upper arch,
// residual springs, contacts per tooth), DIR/{upper,lower}_distances.csv (the occlusionogram
// data), DIR/occlusionogram.png (both arches seen from the occlusal side, colour-coded) and
// DIR/splint.stl (the surgical splint; pipeline/occlusion_run.h). Subcommands: `occlude compare`
// (cmd_occlude_compare.cpp) and `occlude autorotate` (cmd_occlude_autorotate.cpp).
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli/command.h"
#include "core/json.h"
#include "mesh/mesh_io.h"
#include "occlusion/occlusion_files.h"
#include "core/atomic_file.h"
#include "core/sha256.h"
#include "casework/occlusion/occlusion_run.h"
#include "casework/occlusion/archived_occlusion.h"
#include "ceph/landmark_frame.h"
#include "records/case_landmarks.h"
#include "records/dental_scans.h"
#include "geometry/signed_distance.h"
#include "occlusion/occlusion_benchmark.h"

namespace maxillo::cli {
namespace {

using namespace maxillo::occlusion;

struct OccludeOptions {
  std::filesystem::path upper, lower, pairs, start, out;
  std::string case_text;  // --case: store the outputs as artefacts of this archived case
  casework::OcclusionRunOptions run;
  std::optional<double> splint_clearance_mm;  // unset: kCaseSplintClearanceMm on a case's jaws, else the default
  bool no_splint = false;
};

void print_summary(const casework::OcclusionRun& run, const OccludeOptions& options) {
  for (const auto& note : run.upper_repair.notes) std::cout << "upper arch: " << note << "\n";
  for (const auto& note : run.lower_repair.notes) std::cout << "lower arch: " << note << "\n";
  std::cout << "guided alignment " << (run.record.converged ? "converged" : "iteration_limit") << " after "
            << run.aligned.iterations << " iterations; penetration " << run.aligned.penetration_mm << " mm (allowed "
            << run.allowed_penetration_mm << " mm)\nresidual springs (mm):";
  for (double r : run.aligned.residual_spring_mm) std::cout << " " << r;
  std::cout << "\ncontact vertices < " << options.run.contact_threshold_mm << " mm: upper "
            << run.gram.upper.contact_vertices << ", lower " << run.gram.lower.contact_vertices << "\n";
  if (run.splint) {
    const casework::SplintReport& s = run.splint->report;
    std::printf(
        "splint: %s, %d component(s), %lld triangles, %.0f mm3, thickness %.2f mm where no tooth is (%d columns); "
        "distance to upper %.3f mm, lower %.3f mm; triangles crossing the arches: %lld, %lld (%.1f s)\n",
        s.watertight ? "watertight" : "NOT watertight", s.components, (long long)s.triangles, s.volume_mm3,
        s.thickness_mm, s.thickness_columns, s.min_distance_upper_mm, s.min_distance_lower_mm,
        (long long)s.intersecting_pairs_upper, (long long)s.intersecting_pairs_lower, s.seconds);
  } else if (!run.splint_error.empty()) {
    std::cout << "splint not made: " << run.splint_error << "\n";
  }
  std::cout << "wrote " << (options.out / "occlusion.json").string() << "\n";
}

// The case's augmented jaws (the scanned crowns on the CT's roots, in the CT's frame), for
// `occlude --case CASE` without arch files. Error naming what is missing.
std::pair<TriangleMesh, TriangleMesh> case_arches(const Archive& archive, int64_t case_id,
                                                  const std::string& case_text) {
  auto upper = records::current_augmented_dentition(archive, case_id, records::DentalArch::kUpper);
  auto lower = records::current_augmented_dentition(archive, case_id, records::DentalArch::kLower);
  if (!upper || !lower)
    throw Error(ErrorCode::kNotFound, "case " + std::to_string(case_id),
                std::string("it has no augmented ") + (!upper ? "upper" : "lower") +
                    " jaw: import and register both arches' scans first (`maxillo dental import " + case_text +
                    " --upper FILE --lower FILE`, `maxillo dental register " + case_text + "`)");
  return {std::move(*upper), std::move(*lower)};
}

// The pairs of --pairs, or without it the 4 springs where the arches touch now (the registered
// occlusion: the engine settles it without the teeth passing through each other).
std::vector<SpringPair> spring_pairs(const OccludeOptions& options, const TriangleMesh& upper,
                                     const TriangleMesh& lower) {
  if (!options.pairs.empty()) return read_spring_pairs(options.pairs);
  const DistanceField upper_field(upper), lower_field(lower);
  auto pairs = contact_spring_pairs(upper_field, lower_field, Eigen::Isometry3d::Identity(), 4, 1.0);
  for (SpringPair& pair : pairs) pair.lower = pair.upper;  // at rest where the arches are
  if (pairs.size() < 3)
    throw Error(ErrorCode::kProcessing, "the case's arches",
                "they touch in fewer than 3 places: give the corresponding points with --pairs");
  return pairs;
}

// The splint's clearance on a case's augmented jaws: their scanned crowns keep ridges sharper
// than the splint's 0.25 mm grid resolves, and at the default 0.1 mm the phantom's splint crossed
// 8 and 30 of their triangles (none at 0.2 mm).
constexpr double kCaseSplintClearanceMm = 0.2;

int run_occlude(OccludeOptions options, const GlobalOptions& global) {
  const bool from_case = options.upper.empty();
  if (options.splint_clearance_mm)
    options.run.splint_options.clearance_mm = *options.splint_clearance_mm;
  else if (from_case)
    options.run.splint_options.clearance_mm = kCaseSplintClearanceMm;
  std::optional<Archive> archive;
  int64_t case_id = 0;
  if (!options.case_text.empty()) {
    archive.emplace(Archive::open(resolve_archive_dir(global)));
    case_id = archive->resolve_case(options.case_text);
  }
  auto [upper, lower] = from_case ? case_arches(*archive, case_id, options.case_text)
                                  : std::pair{read_mesh(options.upper), read_mesh(options.lower)};
  const std::vector<SpringPair> pairs = spring_pairs(options, upper, lower);
  const Eigen::Isometry3d start =
      options.start.empty() ? Eigen::Isometry3d::Identity() : read_upper_transform(options.start);
  options.run.splint = !options.no_splint;
  options.run.upper_label = from_case ? "the case's augmented upper jaw (CT frame)" : options.upper.string();
  options.run.lower_label = from_case ? "the case's augmented lower jaw (CT frame)" : options.lower.string();
  const casework::OcclusionRun run =
      casework::run_occlusion(std::move(upper), std::move(lower), pairs, start, options.out, options.run);
  if (archive) {
    std::vector<std::string> inputs;
    if (from_case)  // the registrations the augmented jaws were made with
      for (records::DentalArch arch : records::kBothArches)
        inputs.push_back(records::current_dental_registration(*archive, case_id, arch)->key);
    else
      inputs = {sha256_hex(read_file(options.upper)), sha256_hex(read_file(options.lower))};
    if (!options.pairs.empty()) inputs.push_back(sha256_hex(read_file(options.pairs)));
    casework::store_occlusion_run(*archive, case_id, run, inputs,
                                  anatomical_frame(records::latest_landmarks(*archive, case_id)));
  }
  if (global.json)
    std::cout << records::to_json(run.record).dump(2) << "\n";
  else
    print_summary(run, options);
  return 0;
}

}  // namespace

void attach_occlude_compare(CLI::App& occlude, CommandContext& ctx);
void attach_occlude_autorotate(CLI::App& occlude, CommandContext& ctx);

void attach_occlude(CLI::App& app, CommandContext& ctx) {
  // UPPER, LOWER, --pairs and --out are required unless a subcommand (compare) is given; CLI11
  // would demand them for the subcommands too, so the callback checks them.
  auto options = std::make_shared<OccludeOptions>();
  app.add_option("UPPER", options->upper, "upper arch mesh (STL/PLY/OBJ/VTP), moves (required)")
      ->check(CLI::ExistingFile);
  app.add_option("LOWER", options->lower, "lower arch mesh, fixed (its coordinates are the frame) (required)")
      ->check(CLI::ExistingFile);
  app.add_option("--pairs", options->pairs, "CSV rows ux,uy,uz,lx,ly,lz (mm), at least 3 (required)")
      ->check(CLI::ExistingFile);
  app.add_option("--start", options->start, "JSON with upper_transform (4x4) applied to the upper arch first")
      ->check(CLI::ExistingFile);
  app.add_option("--out", options->out, "output folder (required)");
  app.add_option("--contact-threshold", options->run.contact_threshold_mm, "contact regions below this distance (mm)")
      ->check(CLI::Range(0.01, 10.0))
      ->capture_default_str();
  app.add_option("--tolerance", options->run.tolerance_mm, "extra penetration allowed beyond the start pose's (mm)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--splint-thickness", options->run.splint_options.thickness_mm,
                 "splint: minimum thickness where no tooth is (mm)")
      ->check(CLI::Range(0.5, 10.0))
      ->capture_default_str();
  app.add_option("--splint-voxel", options->run.splint_options.voxel_mm, "splint: grid spacing (mm)")
      ->check(CLI::Range(0.05, 1.0))
      ->capture_default_str();
  app.add_option("--splint-clearance", options->splint_clearance_mm,
                 "splint: gap left around the teeth (mm); default 0.1, 0.2 on a case's augmented jaws")
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--no-splint", options->no_splint, "do not make the surgical splint (DIR/splint.stl)");
  app.add_option("--case", options->case_text,
                 "store occlusion.json, the occlusionogram and the splint as artefacts of this archived case; "
                 "without UPPER and LOWER, occlude the case's augmented jaws (maxillo dental register) in its CT's "
                 "frame, with the springs where they touch unless --pairs is given");
  attach_occlude_compare(app, ctx);
  attach_occlude_autorotate(app, ctx);
  app.callback([options, &ctx, &app] {
    if (!app.get_subcommands().empty()) return;  // a subcommand did the work
    // With --case and no arch files, the case's augmented jaws (and, without --pairs, the springs
    // where they touch).
    const bool from_case = !options->case_text.empty() && options->upper.empty() && options->lower.empty();
    for (const auto& [missing, name] : {std::pair{!from_case && options->upper.empty(), "UPPER"},
                                        {!from_case && options->lower.empty(), "LOWER"},
                                        {!from_case && options->pairs.empty(), "--pairs"},
                                        {options->out.empty(), "--out"}})
      if (missing) throw CLI::RequiredError(name);
    ctx.exit_code = run_occlude(*options, ctx.global);
  });
}

}  // namespace maxillo::cli
