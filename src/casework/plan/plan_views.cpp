#include "casework/plan/plan_views.h"

#include <deque>

#include "core/parallel_slabs.h"
#include "geometry/mesh_transform.h"
#include "mesh/surface_extraction.h"

namespace maxillo::casework {
namespace {

constexpr render::ColourRGB kMovedSegment{0.55, 0.75, 0.95};  // planned position: light blue
constexpr render::ColourRGB kGhost{0.6, 0.6, 0.6};            // pre-operative position
constexpr render::ColourRGB kScrew{0.85, 0.15, 0.1};          // distraction screws: red
constexpr double kGhostOpacity = 0.25;
// The screws run inside the sinuses: the bone is drawn translucent so their axes show through.
constexpr double kFixedBoneOpacity = 0.45;
constexpr double kMovedBoneOpacity = 0.6;
constexpr double kScrewRadiusMm = 1.0;
constexpr double kRodInFrontMm = 12;
constexpr double kFocusMarginMm =
    25;  // around the moved segments and screws  // the activation rod's part in front of the entry point

const SegmentTransform* move_of(const std::vector<SegmentTransform>& moves, planning::Segment segment) {
  for (const auto& m : moves)
    if (m.segment == segment) return &m;
  return nullptr;
}

bool moves(const SegmentTransform* move) { return move && !move->transform.isApprox(Eigen::Isometry3d::Identity()); }

}  // namespace

std::vector<SegmentSurface> segment_surfaces(const planning::OsteotomyResult& cut, int64_t target_triangles) {
  SurfaceOptions options;
  options.keep_largest_components = 0;  // a segment may be several pieces (nasal bones, rami)
  options.target_triangles = target_triangles;
  // One segment per thread, each into its own slot: the same surfaces as one after the other.
  std::vector<SegmentSurface> surfaces(cut.stats.size());
  for_each_slab(0, int(cut.stats.size()),
                [&](int first, int last) {
                  for (int s = first; s < last; ++s) {
                    const planning::Segment segment = cut.stats[size_t(s)].segment;
                    surfaces[size_t(s)] = {segment, extract_surface(cut.segments, uint8_t(segment), options)};
                  }
                },
                {.min_slab_size = 1});
  return surfaces;
}

std::vector<render::ViewFile> render_planned_skeleton(
    const std::vector<SegmentSurface>& surfaces, const std::vector<SegmentTransform>& moves_by_segment,
    const std::vector<ScrewAxis>& screws, const AnatomicalFrame& frame, std::span<const render::StandardView> views,
    const std::filesystem::path& folder, std::string_view prefix, const render::RenderSettings& settings) {
  std::deque<TriangleMesh> owned;  // the scene points into these; a deque never moves its elements
  render::Scene scene, focus;      // focus: what moves, and the screws
  for (const auto& surface : surfaces) {
    const SegmentTransform* move = move_of(moves_by_segment, surface.segment);
    if (!moves(move)) {
      scene.meshes.push_back({&surface.mesh, render::kBoneIvory, kFixedBoneOpacity, {}});
      continue;
    }
    scene.meshes.push_back({&surface.mesh, kGhost, kGhostOpacity, {}});
    owned.push_back(transformed(surface.mesh, move->transform));
    scene.meshes.push_back({&owned.back(), kMovedSegment, kMovedBoneOpacity, {}});
    focus.meshes.push_back(scene.meshes.back());
  }
  for (const auto& screw : screws) {
    owned.push_back(cylinder_mesh(screw.entry - kRodInFrontMm * screw.direction,
                                  screw.entry + screw.length_mm * screw.direction, kScrewRadiusMm));
    scene.meshes.push_back({&owned.back(), kScrew, 1.0, {}});
    focus.meshes.push_back(scene.meshes.back());
  }
  // The camera frames the moved segments and the screws (the midface), not the whole skull.
  render::Bounds bounds = render::scene_bounds(focus.meshes.empty() ? scene : focus);
  bounds.min.array() -= kFocusMarginMm;
  bounds.max.array() += kFocusMarginMm;
  return render::render_view_files(scene, frame, views, folder, prefix, settings, bounds);
}

}  // namespace maxillo::casework
