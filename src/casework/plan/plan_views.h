#pragma once
// Pictures of a plan: the segmented skeleton before and after the planned moves, with the
// distraction screw axes, in the standard clinical views (render/view_files.h).
#include <Eigen/Geometry>
#include <filesystem>
#include <vector>

#include "core/triangle_mesh.h"
#include "planning/osteotomy.h"
#include "casework/plan/transfer_model.h"
#include "render/view_files.h"

namespace maxillo::casework {

struct SegmentSurface {
  planning::Segment segment = planning::Segment::kNone;
  TriangleMesh mesh;  // closed, LPS mm, pre-operative position
};

// One closed surface per segment present in the osteotomy result, each decimated to about
// `target_triangles` (the cranium dominates: a smaller budget per segment keeps renders fast).
std::vector<SegmentSurface> segment_surfaces(const planning::OsteotomyResult& cut, int64_t target_triangles = 80000);

struct SegmentTransform {
  planning::Segment segment = planning::Segment::kNone;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // pre-op -> planned, LPS mm
};

// The planned skeleton: fixed segments in translucent bone colour, each moved segment in its
// planned position (light blue) over a fainter ghost of where it was, and the screws as red
// rods along their axes (from 12 mm in front of the entry point, where the activation rod
// leaves the bone, to the screw's end), visible through the bone. Writes <prefix><view>.png into `folder` for each view.
std::vector<render::ViewFile> render_planned_skeleton(
    const std::vector<SegmentSurface>& surfaces, const std::vector<SegmentTransform>& moves,
    const std::vector<ScrewAxis>& screws, const AnatomicalFrame& frame, std::span<const render::StandardView> views,
    const std::filesystem::path& folder, std::string_view prefix = "plan-",
    const render::RenderSettings& settings = {});

}  // namespace maxillo::casework
