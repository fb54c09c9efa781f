#include "casework/plan/plan_outputs.h"

#include <array>
#include <cstdio>

#include "ceph/landmark_frame.h"
#include "mesh/mesh_io.h"
#include "geometry/mesh_transform.h"
#include "casework/plan/plan_views.h"

#include "report/number_text.h"

namespace maxillo::casework {
namespace {

constexpr double kBoreClearanceMm = 0.2;  // printing tolerance around the screw

using report::fixed;

std::vector<ScrewAxis> screws_of(const planning::PlanResult& result) {
  std::vector<ScrewAxis> screws;
  if (!result.distraction || !result.plan.distraction) return screws;
  const auto& device = result.plan.distraction->device;
  for (const auto* v : {&result.distraction->vectors.right, &result.distraction->vectors.left})
    // The screw runs from the entry point back into the sinus, against the direction of travel.
    screws.push_back({std::string(planning::side_name(v->side)), v->entry, -v->axis, device.screw_length_mm});
  return screws;
}

std::vector<SegmentTransform> transforms_of(const planning::PlanResult& result) {
  std::vector<SegmentTransform> moves;
  for (const auto& m : result.moves) moves.push_back({m.segment, m.transform});
  return moves;
}

}  // namespace

PlanOutputs write_plan_outputs(const LabelVolume& labels, const LandmarkSet& landmarks,
                               const planning::PlanResult& result, const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  PlanOutputs outputs;
  const auto cut = planning::cut_skeleton(labels, planning::resolve_osteotomies(result.plan.osteotomies, landmarks));
  outputs.segments = cut.stats;
  outputs.bone_voxels = cut.input_bone_voxels;

  const auto surfaces = segment_surfaces(cut);
  const auto moves = transforms_of(result);
  for (const auto& surface : surfaces) {
    Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
    for (const auto& m : moves)
      if (m.segment == surface.segment) move = m.transform;
    const auto name = std::string(planning::segment_name(surface.segment));
    const auto file = out_dir / ("planned-" + name + ".stl");
    write_mesh(transformed(surface.mesh, move), file);
    outputs.files.push_back({"planned " + name, file});
  }

  const auto screws = screws_of(result);
  if (!screws.empty()) {
    TransferModelOptions options;
    options.bore_radius_mm = result.plan.distraction->device.screw_diameter_mm / 2 + kBoreClearanceMm;
    outputs.transfer_model = make_transfer_model(cut.segments, screws, options);
    const auto file = out_dir / "transfer-model.stl";
    write_mesh(outputs.transfer_model->mesh, file);
    outputs.files.push_back({"transfer model (STL)", file});
  }

  const std::array views{render::StandardView::Frontal, render::StandardView::Lateral, render::StandardView::Oblique};
  render::RenderSettings settings;
  settings.size = {640, 640};
  for (const auto& view :
       render_planned_skeleton(surfaces, moves, screws, anatomical_frame(landmarks), views, out_dir, "plan-", settings))
    outputs.renders.push_back(view.png);
  return outputs;
}

Json plan_outputs_json(const PlanOutputs& outputs) {
  Json segments = Json::array();
  for (const auto& s : outputs.segments)
    segments.push_back(
        {{"segment", planning::segment_name(s.segment)}, {"voxels", s.voxels}, {"volume_ml", s.volume_ml}});
  Json json{{"segments", segments}, {"bone_voxels", outputs.bone_voxels}};
  if (outputs.transfer_model)
    json["transfer_model"] = {{"watertight", outputs.transfer_model->watertight},
                              {"triangles", outputs.transfer_model->mesh.face_count()},
                              {"volume_ml", outputs.transfer_model->volume_ml}};
  return json;
}

std::vector<report::Block> plan_output_blocks(const records::PlanResultRecord::Osteotomy& osteotomy) {
  std::vector<report::Block> blocks;
  report::Table segments;
  segments.columns = {
      {"bone segment", 0.5}, {"volume (ml)", 0.25, report::Align::Right}, {"voxels", 0.25, report::Align::Right}};
  int64_t total = 0;
  for (const records::PlanResultRecord::Segment& s : osteotomy.segments) {
    segments.rows.push_back({s.segment, fixed(s.volume_ml, 1), std::to_string(s.voxels)});
    total += s.voxels;
  }
  segments.rows.push_back({"all segments / bone and teeth of the CT", "",
                           std::to_string(total) + " / " + std::to_string(osteotomy.bone_voxels)});
  blocks.push_back(report::Paragraph{"Osteotomies: bone segments (every bone and tooth voxel in exactly one)"});
  blocks.push_back(segments);
  if (const auto& m = osteotomy.transfer_model) {
    blocks.push_back(report::KeyValueBlock{{
        {"Transfer model", "midface with a tube along each distraction screw (transfer-model.stl)"},
        {"Printable", m->watertight ? "yes: closed, manifold, consistently oriented" : "NO: the surface is not closed"},
        {"Size", std::to_string(m->triangles) + " triangles, " + fixed(m->volume_ml, 1) + " ml"},
    }});
  }
  return blocks;
}

}  // namespace maxillo::casework
