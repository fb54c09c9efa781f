#include "sections/occlusion_section.h"

#include <cstdio>

#include "archive/artefact_kind.h"
#include "core/atomic_file.h"
#include "core/json.h"
#include "occlusion/occlusion_files.h"
#include "records/derivation.h"
#include "render/render_views.h"

#include "report/number_text.h"

namespace maxillo::sections {
namespace {

using namespace maxillo::occlusion;

using report::fixed;

std::vector<std::string> motion_row(const std::string& label, const AnatomicalMotion& m) {
  return {label,
          fixed(m.anterior_mm, 2),
          fixed(m.superior_mm, 2),
          fixed(m.left_mm, 2),
          fixed(m.pitch_deg, 2),
          fixed(m.roll_deg, 2),
          fixed(m.yaw_deg, 2)};
}

report::Table transform_table(const casework::OcclusionRun& run, const AnatomicalFrame& frame) {
  report::Table table;
  table.columns = {{"upper arch", 0.31},
                   {"anterior mm", 0.115, report::Align::Right},
                   {"superior mm", 0.115, report::Align::Right},
                   {"left mm", 0.115, report::Align::Right},
                   {"pitch °", 0.115, report::Align::Right},
                   {"roll °", 0.115, report::Align::Right},
                   {"yaw °", 0.115, report::Align::Right}};
  const Eigen::Vector3d centroid = run.upper.vertices.colwise().mean().transpose();
  table.rows.push_back(
      motion_row("final occlusion (from the scanned position)", anatomical_motion(run.aligned.pose, frame, centroid)));
  table.rows.push_back(
      motion_row("guided alignment (from the start position)",
                 anatomical_motion(run.aligned.pose * run.start.inverse(), frame, run.start * centroid)));
  return table;
}

// One row per tooth with a contact (all teeth of a fused arch are one "tooth").
report::Table contacts_table(const casework::OcclusionRun& run) {
  report::Table table;
  table.columns = {{"arch", 0.2},
                   {"tooth (component)", 0.2, report::Align::Right},
                   {"contact vertices", 0.2, report::Align::Right},
                   {"contact area mm²", 0.2, report::Align::Right},
                   {"closest mm", 0.2, report::Align::Right}};
  for (const auto& [name, arch] : {std::pair{"upper", &run.gram.upper}, {"lower", &run.gram.lower}})
    for (const ToothContacts& t : arch->teeth)
      if (t.contact_vertices > 0)
        table.rows.push_back({name, std::to_string(t.component + 1), std::to_string(t.contact_vertices),
                              fixed(t.contact_area_mm2, 1), fixed(t.min_distance_mm, 2)});
  return table;
}

report::KeyValueBlock alignment_facts(const casework::OcclusionRun& run) {
  std::string springs;
  for (double r : run.aligned.residual_spring_mm) springs += (springs.empty() ? "" : ", ") + fixed(r, 2);
  const bool converged = run.aligned.status == occlusion::AlignmentStatus::Converged;
  return {{{"Guided alignment", std::string(converged ? "converged" : "iteration_limit") + " after " +
                                    std::to_string(run.aligned.iterations) + " iterations"},
           {"Residual springs", springs + " mm"},
           {"Deepest penetration",
            fixed(run.aligned.penetration_mm, 2) + " mm (allowed " + fixed(run.allowed_penetration_mm, 2) + " mm)"},
           {"Contacts below " + fixed(run.contact_threshold_mm, 1) + " mm",
            std::to_string(run.gram.upper.contact_vertices) + " upper and " +
                std::to_string(run.gram.lower.contact_vertices) + " lower vertices, " +
                fixed(run.gram.upper.contact_area_mm2, 1) + " mm² on the upper arch"}}};
}

report::KeyValueBlock splint_facts(const casework::OcclusionRun& run) {
  if (!run.splint) return {{{"Splint", run.splint_error.empty() ? "not made" : "not made: " + run.splint_error}}};
  const casework::SplintReport& r = run.splint->report;
  return {{{"Splint",
            "splint.stl, " + std::to_string(r.triangles) + " triangles, " + fixed(r.volume_mm3 / 1000, 2) + " cm³"},
           {"Watertight", r.watertight && r.components == 1 ? "yes (one closed piece)" : "no"},
           {"Thickness where no tooth is",
            r.thickness_columns == 0
                ? "not measured (no tooth-free column)"
                : fixed(r.thickness_mm, 2) + " mm (thinnest of " + std::to_string(r.thickness_columns) + " columns)"},
           {"Fit", "closest " + fixed(r.min_distance_upper_mm, 2) + " mm to the upper arch, " +
                       fixed(r.min_distance_lower_mm, 2) + " mm to the lower; " +
                       std::to_string(r.intersecting_pairs_upper + r.intersecting_pairs_lower) +
                       " triangles crossing the teeth"}}};
}

}  // namespace

AnatomicalMotion anatomical_motion(const Eigen::Isometry3d& motion, const AnatomicalFrame& frame,
                                   const Eigen::Vector3d& reference) {
  const Eigen::Vector3d shift = motion * reference - reference;
  const Eigen::AngleAxisd rotation(motion.linear());
  const Eigen::Vector3d rotation_deg = rotation.axis() * rotation.angle() * 180.0 / M_PI;
  AnatomicalMotion m;
  m.anterior_mm = shift.dot(frame.anterior);
  m.superior_mm = shift.dot(frame.superior);
  m.left_mm = shift.dot(frame.left);
  m.pitch_deg = -rotation_deg.dot(frame.left);  // front up: a turn from anterior towards superior
  m.roll_deg = rotation_deg.dot(frame.anterior);
  m.yaw_deg = rotation_deg.dot(frame.superior);
  return m;
}

report::Section occlusion_section(const casework::OcclusionRun& run, const AnatomicalFrame& frame,
                                  const std::filesystem::path& splint_png) {
  report::Section section{"occlusion", {}};
  section.blocks.push_back(report::Paragraph{
      "Virtual occlusion: the upper dental arch was brought onto the lower one by spring-guided alignment "
      "between corresponding points, without the teeth passing through each other. The occlusionogram shows "
      "each arch from its occlusal side, coloured by the distance to the opposing arch."});
  report::ImageGrid images;
  images.per_row = splint_png.empty() ? 1 : 2;
  images.figures.push_back(
      {run.folder / "occlusionogram.png", "Occlusionogram: upper arch (left), lower arch (right)"});
  if (!splint_png.empty()) images.figures.push_back({splint_png, "Surgical splint on the lower arch"});
  section.blocks.push_back(images);
  section.blocks.push_back(alignment_facts(run));
  section.blocks.push_back(report::Paragraph{"Contacts per tooth"});
  section.blocks.push_back(contacts_table(run));
  section.blocks.push_back(report::Paragraph{"Final occlusion in the anatomical frame"});
  section.blocks.push_back(transform_table(run, frame));
  section.blocks.push_back(report::Note{
      std::string("Translation of the upper arch's centroid; rotation in degrees (rotation-vector components): "
                  "pitch positive front up, roll positive left side up, yaw positive front to the patient's left. "
                  "Frame: ") +
      (frame.source == FrameSource::Frankfort ? "Frankfort horizontal from landmarks." : "scanner axes.")});
  section.blocks.push_back(report::Paragraph{"Surgical splint"});
  section.blocks.push_back(splint_facts(run));
  return section;
}

void render_splint(const casework::OcclusionRun& run, const AnatomicalFrame& frame, const std::filesystem::path& png) {
  render::Scene scene;
  scene.meshes.push_back({&run.lower, render::kTeethWhite, 1.0, std::nullopt});
  if (run.splint) scene.meshes.push_back({&run.splint->mesh, render::ColourRGB{0.45, 0.7, 0.95}, 0.85, std::nullopt});
  const render::Bounds bounds = render::scene_bounds(scene);
  // From the front and 45 degrees above, so the occlusal side of the splint shows: the frontal
  // view of a frame pitched down (still right-handed: anterior x left = superior).
  AnatomicalFrame tilted = frame;
  tilted.anterior = (frame.anterior + frame.superior).normalized();
  tilted.superior = (frame.superior - frame.anterior).normalized();
  const render::Camera camera = render::standard_camera(render::StandardView::Frontal, tilted, bounds, 1.0);
  render::RenderSettings settings;
  settings.size = {700, 700};
  render::write_png(render::render_scene(scene, std::span(&camera, 1), settings).front(), png);
}

void store_occlusion_artefacts(Archive& archive, int64_t case_id, const casework::OcclusionRun& run,
                               const std::vector<std::string>& input_hashes) {
  const std::string key =
      records::derivation_key(input_hashes, {{"start_transform", occlusion::transform_to_json(run.start)},
                                             {"contact_threshold_mm", run.contact_threshold_mm},
                                             {"splint", run.splint.has_value()}});
  const auto store = [&](const std::string& kind, const std::string& file, const std::string& media_type) {
    if (archive.find_artefact(case_id, kind, key)) return;  // same inputs, same program: already stored
    const std::string sha = archive.store_object(read_file(run.folder / file));
    archive.add_artefact(NewArtefact{case_id, kind, sha, media_type, key, "{}"});
  };
  store(kind_name(ArtefactKind::kOcclusion), "occlusion.json", "application/json");
  store(kind_name(ArtefactKind::kOcclusionogram), "occlusionogram.png", "image/png");
  if (run.splint) store(kind_name(ArtefactKind::kSplint), "splint.stl", "model/stl");
}

}  // namespace maxillo::sections
