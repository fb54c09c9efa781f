#include "sections/occlusion_section.h"

#include <cmath>
#include <string>
#include <vector>

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

report::Table transform_table(const records::OcclusionRecord& o, const AnatomicalFrame& frame) {
  report::Table table;
  table.columns = {{"upper arch", 0.31},
                   {"anterior mm", 0.115, report::Align::Right},
                   {"superior mm", 0.115, report::Align::Right},
                   {"left mm", 0.115, report::Align::Right},
                   {"pitch °", 0.115, report::Align::Right},
                   {"roll °", 0.115, report::Align::Right},
                   {"yaw °", 0.115, report::Align::Right}};
  const Eigen::Vector3d& centroid = *o.upper_centroid;
  table.rows.push_back(
      motion_row("final occlusion (from the scanned position)", anatomical_motion(o.upper_transform, frame, centroid)));
  table.rows.push_back(motion_row(
      "guided alignment (from the start position)",
      anatomical_motion(o.upper_transform * o.start_transform.inverse(), frame, o.start_transform * centroid)));
  return table;
}

// One row per tooth with a contact (all teeth of a fused arch are one "tooth").
report::Table contacts_table(const records::OcclusionRecord& o) {
  report::Table table;
  table.columns = {{"arch", 0.2},
                   {"tooth (component)", 0.2, report::Align::Right},
                   {"contact vertices", 0.2, report::Align::Right},
                   {"contact area mm²", 0.2, report::Align::Right},
                   {"closest mm", 0.2, report::Align::Right}};
  for (const auto& [name, arch] : {std::pair{"upper", &o.upper}, {"lower", &o.lower}})
    for (const ToothContacts& t : arch->teeth)
      if (t.contact_vertices > 0)
        table.rows.push_back({name, std::to_string(t.component + 1), std::to_string(t.contact_vertices),
                              fixed(t.contact_area_mm2, 1), fixed(t.min_distance_mm, 2)});
  return table;
}

report::KeyValueBlock alignment_facts(const records::OcclusionRecord& o) {
  std::string springs;
  for (double r : o.residual_spring_mm) springs += (springs.empty() ? "" : ", ") + fixed(r, 2);
  return {{{"Guided alignment", std::string(o.converged ? "converged" : "iteration_limit") + " after " +
                                    std::to_string(o.iterations) + " iterations"},
           {"Residual springs", springs + " mm"},
           {"Deepest penetration",
            fixed(o.penetration_mm, 2) + " mm (allowed " + fixed(o.allowed_penetration_mm, 2) + " mm)"},
           {"Contacts below " + fixed(o.contact_threshold_mm, 1) + " mm",
            std::to_string(o.upper.contact_vertices) + " upper and " + std::to_string(o.lower.contact_vertices) +
                " lower vertices, " + fixed(o.upper.contact_area_mm2, 1) + " mm² on the upper arch"}}};
}

report::KeyValueBlock splint_facts(const records::OcclusionRecord& o) {
  if (!o.splint) return {{{"Splint", o.splint_error.empty() ? "not made" : "not made: " + o.splint_error}}};
  const records::OcclusionRecord::Splint& r = *o.splint;
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

report::Section occlusion_section(const records::StoredOcclusion& stored, const AnatomicalFrame& frame) {
  const records::OcclusionRecord& o = stored.record;
  report::Section section{"occlusion", {}};
  section.blocks.push_back(report::Paragraph{
      "Virtual occlusion: the upper dental arch was brought onto the lower one by spring-guided alignment "
      "between corresponding points, without the teeth passing through each other. The occlusionogram shows "
      "each arch from its occlusal side, coloured by the distance to the opposing arch."});
  report::ImageGrid images;
  images.per_row = stored.splint_render ? 2 : 1;
  images.figures.push_back({stored.occlusionogram, "Occlusionogram: upper arch (left), lower arch (right)"});
  if (stored.splint_render) images.figures.push_back({*stored.splint_render, "Surgical splint on the lower arch"});
  section.blocks.push_back(images);
  section.blocks.push_back(alignment_facts(o));
  section.blocks.push_back(report::Paragraph{"Contacts per tooth"});
  section.blocks.push_back(contacts_table(o));
  section.blocks.push_back(report::Paragraph{"Final occlusion in the anatomical frame"});
  if (o.upper_centroid) {
    section.blocks.push_back(transform_table(o, frame));
    section.blocks.push_back(report::Note{
        std::string("Translation of the upper arch's centroid; rotation in degrees (rotation-vector components): "
                    "pitch positive front up, roll positive left side up, yaw positive front to the patient's left. "
                    "Frame: ") +
        (frame.source == FrameSource::Frankfort ? "Frankfort horizontal from landmarks." : "scanner axes.")});
  } else {
    section.blocks.push_back(
        report::Note{"Not shown: this occlusion was stored before its arch's centroid was "
                     "kept (format version 1); run the occlusion again to see it."});
  }
  section.blocks.push_back(report::Paragraph{"Surgical splint"});
  section.blocks.push_back(splint_facts(o));
  return section;
}

}  // namespace maxillo::sections
