// Profile charts keep millimetres equal on both axes: a circle is drawn round, in a wide and in a
// tall image, and lengths along x and y keep their ratio.
#include <gtest/gtest.h>

#include <cmath>

#include "chart_pixels.h"
#include "core/error.h"
#include "core/temporary_folder.h"
#include "render/chart.h"

namespace maxillo::render {
namespace {

// A circle of radius 10 mm about (0, 0) and a 120 mm horizontal line below it: data four times
// wider than tall, so an unequal scale would squash the circle.
ProfileChart circle_and_line() {
  ProfileChart chart;
  chart.title = "mid-sagittal profile";
  ChartSeries circle{"circle", {}, {}, ColourRGB{0.9, 0.0, 0.0}};
  for (int i = 0; i <= 200; ++i) {
    circle.xs.push_back(10 * std::cos(2 * M_PI * i / 200));
    circle.ys.push_back(10 * std::sin(2 * M_PI * i / 200));
  }
  chart.curves = {circle, {"line", {-60, 60}, {-15, -15}, ColourRGB{0.0, 0.0, 0.9}}};
  return chart;
}

void expect_equal_scale(const ImageSize& size) {
  const RgbImage image = render_profile_chart(circle_and_line(), {size});
  ASSERT_EQ(image.width, size.width);
  const auto circle = test::find_colour(image, {0.9, 0.0, 0.0});
  const auto line = test::find_colour(image, {0.0, 0.0, 0.9});
  ASSERT_GT(circle.count, 100);
  // Measure the circle within 30 mm of the line's middle (x = 0): the legend's colour sample of
  // the circle sits at the plot's top right corner, farther out.
  const int centre = (line.min_x + line.max_x) / 2, reach = line.width() / 4;
  int left = 1 << 30, right = -1, top = 1 << 30, bottom = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = centre - reach; x <= centre + reach; ++x) {
      if (!test::near_colour(image.at(x, y), {0.9, 0.0, 0.0})) continue;
      left = std::min(left, x), right = std::max(right, x), top = std::min(top, y), bottom = std::max(bottom, y);
    }
  const double width = right - left, height = bottom - top;
  EXPECT_NEAR(width / height, 1.0, 0.04) << width << " x " << height << " px in " << size.width << "x" << size.height;
  // 120 mm of line against the circle's 20 mm diameter.
  EXPECT_NEAR(double(line.width()) / width, 6.0, 0.3);
}

TEST(ProfileChart, CircleStaysRoundInAWideImage) { expect_equal_scale({800, 400}); }

TEST(ProfileChart, CircleStaysRoundInATallImage) { expect_equal_scale({400, 700}); }

TEST(ProfileChart, PngIsTheRenderedImage) {
  TemporaryFolder folder("maxillo-profile-test");
  write_profile_chart_png(circle_and_line(), folder / "profile.png", {{500, 400}});
  EXPECT_EQ(read_png(folder / "profile.png").pixels, render_profile_chart(circle_and_line(), {{500, 400}}).pixels);
}

TEST(ProfileChart, MalformedCurvesAreRefused) {
  ProfileChart chart = circle_and_line();
  chart.curves[0].ys.pop_back();
  EXPECT_THROW(render_profile_chart(chart), Error);
  chart.curves.clear();
  EXPECT_THROW(render_profile_chart(chart), Error);
}

}  // namespace
}  // namespace maxillo::render
