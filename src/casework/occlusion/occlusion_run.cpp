#include "casework/occlusion/occlusion_run.h"

#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"
#include "mesh/mesh_io.h"
#include "occlusion/occlusion_files.h"
#include "render/render_views.h"

namespace maxillo::casework {
namespace {

using namespace maxillo::occlusion;

records::OcclusionRecord::Arch arch_record(const ArchDistances& arch) {
  return {arch.contact_vertices, arch.contact_area_mm2, arch.teeth};
}

records::OcclusionRecord::Splint splint_record(const Splint& s, const SplintOptions& o) {
  const SplintReport& r = s.report;
  return {.file = "splint.stl",
          .minimum_thickness_mm = o.thickness_mm,
          .imprint_depth_mm = o.imprint_depth_mm,
          .clearance_mm = o.clearance_mm,
          .voxel_mm = o.voxel_mm,
          .thickness_mm = r.thickness_mm,
          .thickness_columns = r.thickness_columns,
          .volume_mm3 = r.volume_mm3,
          .triangles = r.triangles,
          .watertight = r.watertight,
          .components = r.components,
          .min_distance_upper_mm = r.min_distance_upper_mm,
          .min_distance_lower_mm = r.min_distance_lower_mm,
          .intersecting_pairs_upper = r.intersecting_pairs_upper,
          .intersecting_pairs_lower = r.intersecting_pairs_lower,
          .seconds = r.seconds};
}

// What occlusion.json holds of the run.
records::OcclusionRecord occlusion_record(const OcclusionRun& run, const OcclusionRunOptions& options) {
  records::OcclusionRecord record;
  record.upper_file = options.upper_label;
  record.lower_file = options.lower_label;
  record.frame = "lower file coordinates (mm); upper_transform maps upper file coordinates into it";
  record.upper_transform = run.aligned.pose;
  record.start_transform = run.start;
  record.upper_centroid = run.upper.vertices.colwise().mean().transpose();
  record.converged = run.aligned.status == AlignmentStatus::Converged;
  record.iterations = run.aligned.iterations;
  record.residual_spring_mm = run.aligned.residual_spring_mm;
  record.penetration_mm = run.aligned.penetration_mm;
  record.allowed_penetration_mm = run.allowed_penetration_mm;
  record.intersecting_triangle_pairs = int64_t(run.intersecting_triangle_pairs);
  record.contact_threshold_mm = options.contact_threshold_mm;
  record.upper = arch_record(run.gram.upper);
  record.lower = arch_record(run.gram.lower);
  record.upper_repair = run.upper_repair;
  record.lower_repair = run.lower_repair;
  if (run.splint) record.splint = splint_record(*run.splint, options.splint_options);
  record.splint_error = run.splint_error;
  record.files = run.files;
  return record;
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

}  // namespace

OcclusionRun compute_occlusion(TriangleMesh upper, TriangleMesh lower, const std::vector<SpringPair>& pairs,
                               const Eigen::Isometry3d& start, const OcclusionRunOptions& options) {
  OcclusionRun run;
  run.upper_repair = repair_arch(upper);
  run.lower_repair = repair_arch(lower);
  run.upper = upper;
  run.start = start;
  run.lower = lower;

  MotionOptions motion;
  motion.penetration_tolerance_mm = options.tolerance_mm;
  const DistanceField upper_field(run.upper), lower_field(run.lower);
  MotionEngine engine(upper_field, lower_field, start, motion);
  run.aligned = align_guided(engine, pairs);
  run.allowed_penetration_mm = engine.allowed_penetration_mm();
  OcclusionogramOptions gram_options;
  gram_options.contact_threshold_mm = options.contact_threshold_mm;
  run.contact_threshold_mm = options.contact_threshold_mm;
  run.gram = compute_occlusionogram(upper_field, lower_field, run.aligned.pose, gram_options);
  run.intersecting_triangle_pairs = lower_field.tree().intersecting_faces(upper_field.tree(), run.aligned.pose).size();

  if (options.splint) {
    try {
      run.splint = make_splint(upper_field, lower_field, run.aligned.pose, options.splint_options);
    } catch (const Error& e) {
      run.splint_error = e.what();
    }
  }
  return run;
}

void write_occlusion_outputs(OcclusionRun& run, const std::filesystem::path& folder,
                             const OcclusionRunOptions& options) {
  run.folder = folder;
  std::filesystem::create_directories(folder);
  write_distances(run.upper, run.aligned.pose, run.gram.upper, folder / "upper_distances.csv");
  write_distances(run.lower, Eigen::Isometry3d::Identity(), run.gram.lower, folder / "lower_distances.csv");
  const TriangleMesh upper_placed = placed(run.upper, run.aligned.pose);
  render::write_png(
      side_by_side(render_arch(upper_placed, run.gram.upper.distance_mm, options.contact_threshold_mm, -1),
                   render_arch(run.lower, run.gram.lower.distance_mm, options.contact_threshold_mm, +1)),
      folder / "occlusionogram.png");
  run.files = {"occlusionogram.png", "upper_distances.csv", "lower_distances.csv"};
  if (run.splint) {
    write_mesh(run.splint->mesh, folder / "splint.stl");
    run.files.push_back("splint.stl");
  }
  run.record = occlusion_record(run, options);
  write_file_atomically(folder / "occlusion.json", to_json(run.record).dump(2) + "\n");
}

OcclusionRun run_occlusion(TriangleMesh upper, TriangleMesh lower, const std::vector<SpringPair>& pairs,
                           const Eigen::Isometry3d& start, const std::filesystem::path& folder,
                           const OcclusionRunOptions& options) {
  std::filesystem::create_directories(folder);  // an unwritable folder fails before the work
  OcclusionRun run = compute_occlusion(std::move(upper), std::move(lower), pairs, start, options);
  write_occlusion_outputs(run, folder, options);
  return run;
}

}  // namespace maxillo::casework
