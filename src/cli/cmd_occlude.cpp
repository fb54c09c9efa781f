// maxillo occlude UPPER LOWER --pairs PAIRS.csv [--start START.json] --out DIR: virtual occlusion
// (thesis ch. 7). Reads both arches (STL/PLY/OBJ/VTP; the lower arch fixes the frame), repairs
// shell orientation, places the upper arch by START's upper_transform, pulls it towards the
// lower arch with the point pairs as springs while contacts stop it (guided alignment), and
// writes DIR/occlusion.json (final 4x4 upper_transform relative to the input upper arch,
// residual springs, contacts per tooth), DIR/{upper,lower}_distances.csv (the occlusionogram
// data) and DIR/occlusionogram.png (both arches seen from the occlusal side, colour-coded).
#include <fstream>
#include <iostream>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json.h"
#include "mesh/mesh_io.h"
#include "occlusion/arch_repair.h"
#include "occlusion/occlusion_files.h"
#include "occlusion/occlusionogram.h"
#include "render/render_views.h"

namespace maxillo::cli {
namespace {

using namespace maxillo::occlusion;

struct OccludeOptions {
  std::filesystem::path upper, lower, pairs, start, out;
  double contact_threshold_mm = 1.0;
  double tolerance_mm = 0.05;
};

Json repair_json(const ArchRepairReport& r) {
  return {{"shells", r.shells},
          {"shells_flipped", r.shells_flipped},
          {"degenerate_faces_removed", r.degenerate_faces_removed},
          {"open_edges", r.open_edges},
          {"notes", r.notes}};
}

Json teeth_json(const ArchDistances& arch) {
  Json teeth = Json::array();
  for (const ToothContacts& t : arch.teeth)
    teeth.push_back({{"component", t.component},
                     {"vertices", t.vertices},
                     {"contact_vertices", t.contact_vertices},
                     {"contact_area_mm2", t.contact_area_mm2},
                     {"min_distance_mm", t.min_distance_mm}});
  return {{"contact_vertices", arch.contact_vertices}, {"contact_area_mm2", arch.contact_area_mm2}, {"teeth", teeth}};
}

void write_distances(const TriangleMesh& mesh, const Eigen::Isometry3d& to_common, const ArchDistances& arch,
                     const std::filesystem::path& path) {
  std::string text = "vertex,x_mm,y_mm,z_mm,distance_mm,tooth\n";
  char line[160];
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector3d x = to_common * Eigen::Vector3d(mesh.vertices.row(v).transpose());
    std::snprintf(line, sizeof line, "%lld,%.4f,%.4f,%.4f,%.4f,%d\n", (long long)v, x.x(), x.y(), x.z(),
                  arch.distance_mm[size_t(v)], arch.tooth_of_vertex[size_t(v)]);
    text += line;
  }
  write_file_atomically(path, text);
}

TriangleMesh placed(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  TriangleMesh out = mesh;
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
    out.vertices.row(v) = (pose * Eigen::Vector3d(mesh.vertices.row(v).transpose())).transpose();
  return out;
}

// One arch seen from the occlusal side (lower: from above, upper: from below), anterior up.
render::RgbImage render_arch(const TriangleMesh& mesh, const std::vector<double>& distances, double threshold,
                             double from_z) {
  render::Scene scene;
  render::SceneMesh item;
  item.mesh = &mesh;
  item.scalars = render::VertexScalars{distances, 0.0, 2 * threshold, render::ColourMap::Sequential,
                                       "distance to opposing arch (mm)"};
  scene.meshes.push_back(item);
  const render::Bounds bounds = render::scene_bounds(scene);
  render::Camera camera;
  camera.focal_point = bounds.centre();
  camera.position = bounds.centre() + Eigen::Vector3d(0, 0, from_z * 300);
  camera.view_up = -Eigen::Vector3d::UnitY();
  camera.parallel_scale_mm = 0.6 * std::max(bounds.max.x() - bounds.min.x(), bounds.max.y() - bounds.min.y());
  render::RenderSettings settings;
  settings.size = {900, 900};
  return render::render_scene(scene, std::span(&camera, 1), settings).front();
}

render::RgbImage side_by_side(const render::RgbImage& left, const render::RgbImage& right) {
  render::RgbImage out;
  out.width = left.width + right.width;
  out.height = std::max(left.height, right.height);
  out.pixels.assign(size_t(out.width) * size_t(out.height) * 3, 255);
  for (int y = 0; y < out.height; ++y) {
    if (y < left.height) std::copy_n(left.at(0, y), 3 * left.width, &out.pixels[3 * size_t(y) * size_t(out.width)]);
    if (y < right.height)
      std::copy_n(right.at(0, y), 3 * right.width,
                  &out.pixels[3 * (size_t(y) * size_t(out.width) + size_t(left.width))]);
  }
  return out;
}

int run_occlude(const OccludeOptions& options, const GlobalOptions& global) {
  TriangleMesh upper = read_mesh(options.upper), lower = read_mesh(options.lower);
  const ArchRepairReport upper_repair = repair_arch(upper), lower_repair = repair_arch(lower);
  const std::vector<SpringPair> pairs = read_spring_pairs(options.pairs);
  const Eigen::Isometry3d start =
      options.start.empty() ? Eigen::Isometry3d::Identity() : read_upper_transform(options.start);
  std::filesystem::create_directories(options.out);

  MotionOptions motion;
  motion.penetration_tolerance_mm = options.tolerance_mm;
  const DistanceField upper_field(upper), lower_field(lower);
  MotionEngine engine(upper_field, lower_field, start, motion);
  const AlignmentResult aligned = align_guided(engine, pairs);
  OcclusionogramOptions gram_options;
  gram_options.contact_threshold_mm = options.contact_threshold_mm;
  const Occlusionogram gram = compute_occlusionogram(engine.upper(), engine.lower(), aligned.pose, gram_options);
  const auto intersecting = engine.lower().tree().intersecting_faces(engine.upper().tree(), aligned.pose);

  write_distances(upper, aligned.pose, gram.upper, options.out / "upper_distances.csv");
  write_distances(lower, Eigen::Isometry3d::Identity(), gram.lower, options.out / "lower_distances.csv");
  const TriangleMesh upper_placed = placed(upper, aligned.pose);
  render::write_png(side_by_side(render_arch(upper_placed, gram.upper.distance_mm, options.contact_threshold_mm, -1),
                                 render_arch(lower, gram.lower.distance_mm, options.contact_threshold_mm, +1)),
                    options.out / "occlusionogram.png");

  Json result{{"upper_file", options.upper.string()},
              {"lower_file", options.lower.string()},
              {"frame", "lower file coordinates (mm); upper_transform maps upper file coordinates into it"},
              {"upper_transform", transform_to_json(aligned.pose)},
              {"start_transform", transform_to_json(start)},
              {"status", aligned.status == AlignmentStatus::Converged ? "converged" : "iteration_limit"},
              {"iterations", aligned.iterations},
              {"residual_spring_mm", aligned.residual_spring_mm},
              {"penetration_mm", aligned.penetration_mm},
              {"allowed_penetration_mm", engine.allowed_penetration_mm()},
              {"intersecting_triangle_pairs", intersecting.size()},
              {"contact_threshold_mm", options.contact_threshold_mm},
              {"upper", teeth_json(gram.upper)},
              {"lower", teeth_json(gram.lower)},
              {"repairs", {{"upper", repair_json(upper_repair)}, {"lower", repair_json(lower_repair)}}},
              {"files", {"occlusionogram.png", "upper_distances.csv", "lower_distances.csv"}}};
  write_file_atomically(options.out / "occlusion.json", result.dump(2) + "\n");
  if (global.json) {
    std::cout << result.dump(2) << "\n";
  } else {
    for (const auto& note : upper_repair.notes) std::cout << "upper arch: " << note << "\n";
    for (const auto& note : lower_repair.notes) std::cout << "lower arch: " << note << "\n";
    std::cout << "guided alignment " << result["status"].get<std::string>() << " after " << aligned.iterations
              << " iterations; penetration " << aligned.penetration_mm << " mm (allowed "
              << engine.allowed_penetration_mm() << " mm)\nresidual springs (mm):";
    for (double r : aligned.residual_spring_mm) std::cout << " " << r;
    std::cout << "\ncontact vertices < " << options.contact_threshold_mm << " mm: upper " << gram.upper.contact_vertices
              << ", lower " << gram.lower.contact_vertices << "\nwrote " << (options.out / "occlusion.json").string()
              << "\n";
  }
  return 0;
}

}  // namespace

void attach_occlude(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<OccludeOptions>();
  app.add_option("UPPER", options->upper, "upper arch mesh (STL/PLY/OBJ/VTP), moves")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("LOWER", options->lower, "lower arch mesh, fixed (its coordinates are the frame)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--pairs", options->pairs, "CSV rows ux,uy,uz,lx,ly,lz (mm), at least 3")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--start", options->start, "JSON with upper_transform (4x4) applied to the upper arch first")
      ->check(CLI::ExistingFile);
  app.add_option("--out", options->out, "output folder")->required();
  app.add_option("--contact-threshold", options->contact_threshold_mm, "contact regions below this distance (mm)")
      ->check(CLI::Range(0.01, 10.0))
      ->capture_default_str();
  app.add_option("--tolerance", options->tolerance_mm, "extra penetration allowed beyond the start pose's (mm)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.callback([options, &ctx] { ctx.exit_code = run_occlude(*options, ctx.global); });
}

}  // namespace maxillo::cli
