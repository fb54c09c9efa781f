#include "render/render_views.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <set>

#include "core/error.h"
#include "render/anatomical_views.h"
#include "test_meshes.h"

namespace maxillo::render {
namespace {
namespace fs = std::filesystem;
using testing::box;
using testing::uv_sphere;

constexpr ImageSize kSmall{256, 256};

bool is_background(const std::uint8_t* px, const ColourRGB& background = kBackgroundGrey) {
  const double ref[3] = {background.r * 255, background.g * 255, background.b * 255};
  for (int c = 0; c < 3; ++c)
    if (std::abs(px[c] - ref[c]) > 40) return false;
  return true;
}

struct Silhouette {
  long pixels = 0;
  int min_x = 1 << 30, max_x = -1, min_y = 1 << 30, max_y = -1;
  double width() const { return max_x - min_x + 1; }
  double height() const { return max_y - min_y + 1; }
  double centre_x() const { return 0.5 * (min_x + max_x); }
};

Silhouette silhouette(const RgbImage& image) {
  Silhouette s;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!is_background(image.at(x, y))) {
        ++s.pixels;
        s.min_x = std::min(s.min_x, x), s.max_x = std::max(s.max_x, x);
        s.min_y = std::min(s.min_y, y), s.max_y = std::max(s.max_y, y);
      }
  return s;
}

std::size_t distinct_colours(const RgbImage& image) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < image.pixels.size(); i += 3)
    colours.insert(image.pixels[i] << 16 | image.pixels[i + 1] << 8 | image.pixels[i + 2]);
  return colours.size();
}

Camera frontal_camera_for(const Scene& scene) {
  return standard_camera(StandardView::Frontal, AnatomicalFrame{}, scene_bounds(scene), 1.0);
}

TEST(RenderScene, SphereCoversItsProjectedArea) {
  const double radius = 30;
  auto sphere = uv_sphere({5, -3, 7}, radius, 180, 360);
  Scene scene{{{&sphere, kBoneIvory, 1.0, {}}}, {}};
  Camera camera = frontal_camera_for(scene);
  camera.parallel_scale_mm = 50;  // visible area 100 x 100 mm
  RenderSettings settings{{512, 512}};
  auto images = render_scene(scene, std::span(&camera, 1), settings);
  ASSERT_EQ(images.size(), 1u);
  const double expected = std::numbers::pi * radius * radius / (100.0 * 100.0);
  const double covered = double(silhouette(images[0]).pixels) / (512.0 * 512.0);
  EXPECT_NEAR(covered / expected, 1.0, 0.02) << "covered " << covered << " expected " << expected;
}

TEST(RenderScene, BoxSilhouetteHasTheExpectedAspectInEachView) {
  // 40 mm left-right, 200 mm antero-posterior, 80 mm high.
  auto slab = box({-20, -100, -40}, {20, 100, 40});
  Scene scene{{{&slab, kBoneIvory, 1.0, {}}}, {}};
  std::vector<Camera> cameras;
  for (auto view : {StandardView::Frontal, StandardView::Lateral})
    cameras.push_back(standard_camera(view, AnatomicalFrame{}, scene_bounds(scene), 1.0));
  auto images = render_scene(scene, cameras, {kSmall});
  auto frontal = silhouette(images[0]), lateral = silhouette(images[1]);
  EXPECT_NEAR(frontal.width() / frontal.height(), 40.0 / 80.0, 0.03);
  EXPECT_NEAR(lateral.width() / lateral.height(), 200.0 / 80.0, 0.08);
  // The longest extent fills the image up to the margins.
  EXPECT_NEAR(lateral.width() / kSmall.width, 1 - 2 * kViewMargin, 0.02);
}

TEST(RenderScene, LateralViewShowsTheFaceOnTheRight) {
  // A head-like ball with a "nose" on its anterior (-y) side.
  auto head = uv_sphere({0, 0, 0}, 60, 40, 80);
  auto nose = uv_sphere({0, -75, 0}, 15, 20, 40);
  Scene scene{{{&head, kBoneIvory, 1.0, {}}, {&nose, {0.8, 0.1, 0.1}, 1.0, {}}}, {}};
  auto camera = standard_camera(StandardView::Lateral, AnatomicalFrame{}, scene_bounds(scene), 1.0);
  auto image = render_scene(scene, std::span(&camera, 1), {kSmall}).front();
  long red_x_sum = 0, red_count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y)[0] > 120 && image.at(x, y)[1] < 60) red_x_sum += x, ++red_count;
  ASSERT_GT(red_count, 100);
  EXPECT_GT(double(red_x_sum) / red_count, 0.75 * image.width);
}

TEST(RenderScene, TranslucentSkinShowsBoneBeneath) {
  auto skin = uv_sphere({0, 0, 0}, 60, 60, 120);
  auto bone = uv_sphere({0, 0, 0}, 35, 60, 120);
  const ColourRGB blue{0.2, 0.3, 0.9};  // far from the skin tone, so blending is measurable
  Scene with_bone{{{&bone, blue, 1.0, {}}, {&skin, kSkinTone, 0.45, {}}}, {}};
  Scene skin_only{{{&skin, kSkinTone, 0.45, {}}}, {}};
  auto camera = frontal_camera_for(with_bone);
  auto a = render_scene(with_bone, std::span(&camera, 1), {kSmall}).front();
  auto b = render_scene(skin_only, std::span(&camera, 1), {kSmall}).front();
  // At the centre the bone changes the colour; near the rim (skin only) it does not.
  const int c = kSmall.width / 2, rim = c + int(0.85 * (c * (1 - 2 * kViewMargin)));
  int centre_difference = 0, rim_difference = 0;
  for (int k = 0; k < 3; ++k) {
    centre_difference += std::abs(a.at(c, c)[k] - b.at(c, c)[k]);
    rim_difference += std::abs(a.at(rim, c)[k] - b.at(rim, c)[k]);
  }
  EXPECT_GT(centre_difference, 60);
  EXPECT_LE(rim_difference, 3);
}

TEST(RenderScene, VertexScalarsFollowTheColourMap) {
  auto sphere = uv_sphere({0, 0, 0}, 40, 60, 120);
  VertexScalars heights{{}, -40, 40, ColourMap::Diverging, "height (mm)"};
  for (Eigen::Index v = 0; v < sphere.vertex_count(); ++v) heights.values.push_back(sphere.vertices(v, 2));
  Scene scene{{{&sphere, kBoneIvory, 1.0, heights}}, {}};
  auto camera = frontal_camera_for(scene);
  auto image = render_scene(scene, std::span(&camera, 1), {kSmall}).front();
  // With a colour bar the scene keeps the left 82% of the image, centred there.
  const int x = int(0.41 * kSmall.width);
  const auto* top = image.at(x, kSmall.height / 2 - 70);
  const auto* bottom = image.at(x, kSmall.height / 2 + 70);
  EXPECT_GT(top[0], top[2] + 40) << "upper sphere (z ~ +30 mm) should be red";
  EXPECT_GT(bottom[2], bottom[0] + 30) << "lower sphere (z ~ -30 mm) should be blue";
  // The colour bar's strip on the right shows both ends of the map.
  bool bar_red = false, bar_blue = false;
  for (int y = 0; y < image.height; ++y)
    for (int bx = int(0.82 * image.width); bx < image.width; ++bx) {
      const auto* px = image.at(bx, y);
      bar_red |= px[0] > 150 && px[2] < 80;
      bar_blue |= px[2] > 150 && px[0] < 100;
    }
  EXPECT_TRUE(bar_red && bar_blue);
}

// Markers (scene.h) are drawn over the meshes: a landmark inside an opaque skull (the sella)
// stays visible, where the camera projects it, with its label beside it.
TEST(RenderScene, MarkersInsideAnOpaqueMeshAreDrawnWhereTheyProjectWithTheirLabels) {
  auto skull = uv_sphere({0, 0, 0}, 30, 60, 120);
  Scene scene{{{&skull, kBoneIvory, 1.0, {}}}, {}};
  const ColourRGB red{1, 0, 0};
  scene.markers = {{{0, 0, 0}, "S", red}, {{20, 0, 0}, "PoL", red}};
  Camera camera = frontal_camera_for(scene);
  camera.parallel_scale_mm = 50;  // 512 pixels for 100 mm: 5.12 pixels per mm
  RenderSettings settings{{512, 512}};
  const auto image = render_scene(scene, std::span(&camera, 1), settings).front();
  auto is_marker_red = [](const std::uint8_t* px) { return px[0] > 200 && px[1] < 60 && px[2] < 60; };
  EXPECT_TRUE(is_marker_red(image.at(256, 256))) << "the centre, inside the sphere";
  // The patient's left (+x) is on the image's right in a frontal view: 20 mm = 102 pixels.
  EXPECT_TRUE(is_marker_red(image.at(256 + 102, 256)));
  // The label: dark red text (the marker's colour, darker) just right of the marker.
  int text_pixels = 0;
  for (int y = 240; y < 272; ++y)
    for (int x = 256 + 102 + 6; x < 256 + 102 + 60; ++x) {
      const auto* px = image.at(x, y);
      text_pixels += px[0] > 120 && px[0] < 215 && px[1] < 40 && px[2] < 40;
    }
  EXPECT_GT(text_pixels, 10) << "no label beside the marker";

  // A marker outside the view changes nothing; without markers the sphere is as before.
  Scene with_outside = scene;
  with_outside.markers.push_back({{1000, 0, 0}, "far", red});
  EXPECT_EQ(render_scene(with_outside, std::span(&camera, 1), settings).front().pixels, image.pixels);
  Scene bare{{{&skull, kBoneIvory, 1.0, {}}}, {}};
  const auto plain = render_scene(bare, std::span(&camera, 1), settings).front();
  EXPECT_FALSE(is_marker_red(plain.at(256, 256)));
}

TEST(RenderScene, ScalarCountMismatchIsRejected) {
  auto sphere = uv_sphere({0, 0, 0}, 40, 10, 20);
  Scene scene{{{&sphere, kBoneIvory, 1.0, VertexScalars{{1.0, 2.0}, 0, 1, ColourMap::Sequential, ""}}}, {}};
  auto camera = frontal_camera_for(scene);
  EXPECT_THROW(render_scene(scene, std::span(&camera, 1), {kSmall}), Error);
}

TEST(RenderScene, RendersAreDeterministic) {
  auto skin = uv_sphere({0, 0, 0}, 60, 60, 120);
  auto slab = box({-30, -20, -30}, {30, 20, 30});
  Scene scene{{{&slab, kBoneIvory, 1.0, {}}, {&skin, kSkinTone, 0.45, {}}}, {}};
  auto camera = standard_camera(StandardView::Oblique, AnatomicalFrame{}, scene_bounds(scene), 1.0);
  auto first = render_scene(scene, std::span(&camera, 1), {kSmall}).front();
  auto second = render_scene(scene, std::span(&camera, 1), {kSmall}).front();
  EXPECT_TRUE(first.pixels == second.pixels);
}

TEST(RenderScene, PngFilesAreRealAndRoundTrip) {
  const fs::path folder = fs::temp_directory_path() / ("maxillo-render-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  auto skin = uv_sphere({0, 0, 0}, 60, 60, 120);
  auto bone = uv_sphere({0, 0, 0}, 35, 60, 120);
  Scene scene{{{&bone, kBoneIvory, 1.0, {}}, {&skin, kSkinTone, 0.45, {}}}, {}};
  auto camera = standard_camera(StandardView::Oblique, AnatomicalFrame{}, scene_bounds(scene), 1.0);
  auto image = render_scene(scene, std::span(&camera, 1), {kSmall}).front();
  write_png(image, folder / "oblique.png");
  auto reread = read_png(folder / "oblique.png");
  EXPECT_EQ(reread.width, kSmall.width);
  EXPECT_EQ(reread.height, kSmall.height);
  EXPECT_TRUE(reread.pixels == image.pixels);
  EXPECT_GT(distinct_colours(reread), 50u);  // shaded, not blank
  EXPECT_THROW(read_png(folder / "absent.png"), Error);
  fs::remove_all(folder);
}

TEST(RenderScene, MillionTriangleMeshRenders) {
  auto sphere = uv_sphere({0, 0, 0}, 80, 500, 1000);  // 998,000 triangles
  ASSERT_GT(sphere.face_count(), 990'000);
  Scene scene{{{&sphere, kBoneIvory, 1.0, {}}}, {}};
  auto camera = frontal_camera_for(scene);
  const auto start = std::chrono::steady_clock::now();
  auto image = render_scene(scene, std::span(&camera, 1), {{1024, 1024}}).front();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[   TIME   ] 1M-triangle sphere at 1024x1024: %.2f s\n", seconds);
  EXPECT_GT(silhouette(image).pixels, 1024L * 1024 / 2);
}

}  // namespace
}  // namespace maxillo::render

#include "render/view_files.h"

namespace maxillo::render {
namespace {

TEST(RenderViewFiles, WritesOnePngPerViewNamedAfterIt) {
  const fs::path folder = fs::temp_directory_path() / ("maxillo-views-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  auto head = uv_sphere({0, 0, 0}, 60, 30, 60);
  Scene scene{{{&head, kSkinTone, 1.0, {}}}, {}};
  const StandardView views[] = {StandardView::Frontal, StandardView::Lateral, StandardView::Oblique};
  auto files = render_view_files(scene, AnatomicalFrame{}, views, folder, "case7-", {{320, 200}});
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[1].png, folder / "case7-lateral.png");
  for (const auto& file : files) {
    auto image = read_png(file.png);
    EXPECT_EQ(image.width, 320);
    EXPECT_EQ(image.height, 200);
    EXPECT_GT(distinct_colours(image), 20u);
    // Fitted to a wide image: the sphere fills the height up to the margins.
    EXPECT_NEAR(silhouette(image).height() / 200.0, 1 - 2 * kViewMargin, 0.03);
  }
  Scene empty;
  EXPECT_THROW(render_view_files(empty, AnatomicalFrame{}, views, folder), Error);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace maxillo::render
