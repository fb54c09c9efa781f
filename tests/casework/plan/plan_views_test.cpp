// Renders of the planned skeleton: real OSMesa images with the moved maxilla and the screws.
#include <gtest/gtest.h>

#include <cstdlib>

#include "ceph/landmark_frame.h"
#include "geometry/mesh_measures.h"
#include "casework/plan/plan_views.h"
#include "render/render_views.h"
#include "sample/phantom.h"
#include "support/temporary_folder.h"

namespace maxillo::casework {
namespace {

// Pixels whose colour is within `tolerance` of a pure hue direction: red-dominant or blue-dominant.
int64_t count_pixels(const render::RgbImage& image, bool (*match)(const uint8_t*)) {
  int64_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += match(image.at(x, y));
  return n;
}
bool reddish(const uint8_t* p) { return p[0] > p[1] + 50 && p[0] > p[2] + 50; }
bool bluish(const uint8_t* p) { return p[2] > 120 && p[2] > p[0] + 40; }

TEST(PlanViews, ShowTheMovedMaxillaAndTheScrews) {
  PhantomSpec spec;
  spec.spacing_mm = 2.0;
  spec.noise_sigma_hu = 0;
  const auto phantom = make_phantom(spec);
  const auto cut = planning::cut_skeleton(phantom.labels, planning::default_osteotomies(phantom.landmarks, {}));
  const auto surfaces = segment_surfaces(cut, 20000);
  ASSERT_EQ(surfaces.size(), 3u);  // cranium, maxilla, mandible
  for (const auto& s : surfaces) {
    EXPECT_GT(s.mesh.face_count(), 100) << planning::segment_name(s.segment);
    const auto edges = count_edges(s.mesh);  // closed surfaces: no border edge, consistent orientation
    EXPECT_EQ(edges.boundary, 0) << planning::segment_name(s.segment);
    EXPECT_EQ(edges.inconsistent, 0) << planning::segment_name(s.segment);
    EXPECT_GT(signed_volume(s.mesh), 0) << planning::segment_name(s.segment);
  }

  std::vector<SegmentTransform> moves{
      {planning::Segment::kMaxilla, Eigen::Isometry3d(Eigen::Translation3d(0, -10, 0))}};
  std::vector<ScrewAxis> screws{{"right", {-22, -58, -18}, {0, 1, 0}, 26}, {"left", {22, -58, -18}, {0, 1, 0}, 26}};
  TemporaryFolder folder("plan-views");
  const std::array views{render::StandardView::Frontal, render::StandardView::Lateral};
  render::RenderSettings settings;
  settings.size = {320, 320};
  auto files = render_planned_skeleton(surfaces, moves, screws, anatomical_frame(phantom.landmarks), views,
                                       folder.path(), "plan-", settings);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1].png.filename(), "plan-lateral.png");
  const auto lateral = render::read_png(files[1].png);
  EXPECT_EQ(lateral.width, 320);
  EXPECT_GT(count_pixels(lateral, bluish), 500);  // the advanced maxilla
  if (const char* keep = std::getenv("MAXILLO_KEEP_TEST_IMAGES")) std::filesystem::copy_file(files[1].png, keep);
  EXPECT_GT(count_pixels(lateral, reddish), 20);  // the screws, seen through the bone
}

}  // namespace
}  // namespace maxillo::casework
