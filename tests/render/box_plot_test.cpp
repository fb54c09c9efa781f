// Box plots: each group's box stands at its own x position in group order, at the height of its
// values and as tall as their spread; the summary is the type-7 percentiles; bad input is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "chart_pixels.h"
#include "core/error.h"
#include "core/temporary_folder.h"
#include "render/chart.h"

namespace maxillo::render {
namespace {

constexpr ImageSize kSize{640, 400};

// n values evenly spread over [low, high].
std::vector<double> spread(double low, double high, int n = 41) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(low + (high - low) * i / (n - 1));
  return v;
}

BoxPlot three_groups() {
  BoxPlot plot;
  plot.title = "error by case";
  plot.y_title = "distance (mm)";
  plot.groups = {{"low", spread(0, 4)}, {"high", spread(20, 28)}, {"middle", spread(10, 14)}};
  return plot;
}

TEST(BoxPlot, SummaryIsTheType7Percentiles) {
  const auto s = box_plot_summary(spread(1, 101, 101));  // 1, 2, ..., 101
  EXPECT_DOUBLE_EQ(s.p5, 6);
  EXPECT_DOUBLE_EQ(s.p25, 26);
  EXPECT_DOUBLE_EQ(s.p50, 51);
  EXPECT_DOUBLE_EQ(s.p75, 76);
  EXPECT_DOUBLE_EQ(s.p95, 96);
  const auto two = box_plot_summary({0, 10});
  EXPECT_DOUBLE_EQ(two.p25, 2.5);
  EXPECT_DOUBLE_EQ(box_plot_summary({3}).p95, 3);
}

TEST(BoxPlot, GroupsStandInOrderAtTheHeightAndSpreadOfTheirValues) {
  const BoxPlot plot = three_groups();
  const RgbImage image = render_box_plot(plot, {kSize});
  ASSERT_EQ(image.width, kSize.width);
  ASSERT_EQ(image.height, kSize.height);
  const auto low = test::find_colour(image, box_colour(0)), high = test::find_colour(image, box_colour(1)),
             middle = test::find_colour(image, box_colour(2));
  for (const auto& g : {low, high, middle}) ASSERT_GT(g.count, 150);
  // Left to right in group order, not overlapping.
  EXPECT_LT(low.max_x, high.min_x);
  EXPECT_LT(high.max_x, middle.min_x);
  // Larger values are drawn higher (smaller row numbers).
  EXPECT_LT(high.mean_y, middle.mean_y);
  EXPECT_LT(middle.mean_y, low.mean_y);
  // Whisker to whisker (P5-P95) is proportional to the spread: 7.2 mm for "high", 3.6 for the others.
  EXPECT_NEAR(double(high.height()) / low.height(), 2.0, 0.12);
  EXPECT_NEAR(double(middle.height()) / low.height(), 1.0, 0.06);
  // The boxes do not overlap vertically either: "middle" (10-14) lies between the others.
  EXPECT_LT(high.max_y, middle.min_y);
  EXPECT_LT(middle.max_y, low.min_y);
}

TEST(BoxPlot, ReferenceLineIsGreyAcrossThePlot) {
  BoxPlot plot = three_groups();
  plot.reference_y = 0.0;
  const RgbImage image = render_box_plot(plot, {kSize});
  const auto grey = test::find_colour(image, {0.55, 0.55, 0.55}, 12);
  EXPECT_GT(grey.width(), kSize.width / 2);
  EXPECT_GT(grey.mean_y, kSize.height * 0.75);  // 0 mm is at the bottom of this plot (text edges add a few grey pixels)
}

TEST(BoxPlot, PngIsTheRenderedImage) {
  TemporaryFolder folder("maxillo-box-plot-test");
  write_box_plot_png(three_groups(), folder / "box.png", {kSize});
  EXPECT_EQ(read_png(folder / "box.png").pixels, render_box_plot(three_groups(), {kSize}).pixels);
}

TEST(BoxPlot, EmptyOrNonFiniteInputIsRefused) {
  BoxPlot plot = three_groups();
  plot.groups[1].values.clear();
  EXPECT_THROW(render_box_plot(plot, {kSize}), Error);
  plot.groups[1].values = {1.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_THROW(render_box_plot(plot, {kSize}), Error);
  plot.groups.clear();
  EXPECT_THROW(render_box_plot(plot, {kSize}), Error);
  EXPECT_THROW(box_plot_summary({}), Error);
}

}  // namespace
}  // namespace maxillo::render
