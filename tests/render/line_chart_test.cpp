#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "core/temporary_folder.h"
#include "render/chart.h"

namespace maxillo::render {
namespace {

constexpr ImageSize kChartSize{640, 400};

bool near(const std::uint8_t* px, const ColourRGB& colour, int tolerance = 30) {
  const double ref[3] = {colour.r * 255, colour.g * 255, colour.b * 255};
  for (int c = 0; c < 3; ++c)
    if (std::abs(px[c] - ref[c]) > tolerance) return false;
  return true;
}

struct ColourCount {
  long upper = 0;  // pixels of that colour in the upper half of the image
  long lower = 0;
  int min_x = 1 << 30, max_x = -1;
};

ColourCount count(const RgbImage& image, const ColourRGB& colour, int tolerance = 30) {
  ColourCount n;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (near(image.at(x, y), colour, tolerance)) {
        (y < image.height / 2 ? n.upper : n.lower) += 1;
        n.min_x = std::min(n.min_x, x);
        n.max_x = std::max(n.max_x, x);
      }
  return n;
}

// Two horizontal lines: "low" at y = 0, "high" at y = 10, over x = 0..24 months.
LineChart two_lines() {
  LineChart chart;
  chart.x_title = "months";
  chart.y_title = "Wits (mm)";
  chart.series = {{"low", {0, 12, 24}, {0, 0, 0}, std::nullopt}, {"high", {0, 12, 24}, {10, 10, 10}, std::nullopt}};
  return chart;
}

TEST(LineChart, EachSeriesIsDrawnInItsOwnColourWhereItsValuesAre) {
  const LineChart chart = two_lines();
  const RgbImage image = render_line_chart(chart, {kChartSize});
  ASSERT_EQ(image.width, kChartSize.width);
  ASSERT_EQ(image.height, kChartSize.height);

  const ColourRGB low = series_colour(chart, 0), high = series_colour(chart, 1);
  const ColourCount low_pixels = count(image, low), high_pixels = count(image, high);
  // Each line spans most of the plot's width (a legend sample alone would be ~30 px).
  EXPECT_GT(low_pixels.max_x - low_pixels.min_x, kChartSize.width / 2);
  EXPECT_GT(high_pixels.max_x - high_pixels.min_x, kChartSize.width / 2);
  // y = 0 lies below y = 10: the low line's pixels are mostly in the lower half, the high one's in the upper.
  EXPECT_GT(low_pixels.lower, 4 * low_pixels.upper);
  EXPECT_GT(high_pixels.upper, 4 * high_pixels.lower);
  EXPECT_GT(low_pixels.lower, 300);
  EXPECT_GT(high_pixels.upper, 300);
}

TEST(LineChart, BackgroundFillsTheRestAndCornersStayBackground) {
  const RgbImage image = render_line_chart(two_lines(), {kChartSize});
  const ColourRGB white{1, 1, 1};
  long background = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) background += near(image.at(x, y), white, 8);
  EXPECT_GT(background, 0.8 * image.width * image.height);
  EXPECT_TRUE(near(image.at(0, 0), white, 8));
  EXPECT_TRUE(near(image.at(image.width - 1, image.height - 1), white, 8));
}

TEST(LineChart, PaletteColoursAreDistinctAndAnExplicitColourWins) {
  const auto& palette = chart_palette();
  ASSERT_GE(palette.size(), 8u);
  for (std::size_t i = 0; i < palette.size(); ++i)
    for (std::size_t j = i + 1; j < palette.size(); ++j) {
      const double d = std::abs(palette[i].r - palette[j].r) + std::abs(palette[i].g - palette[j].g) +
                       std::abs(palette[i].b - palette[j].b);
      EXPECT_GT(d, 0.25) << i << " vs " << j;
    }
  LineChart chart = two_lines();
  chart.series[1].colour = ColourRGB{0.9, 0.0, 0.0};
  const RgbImage image = render_line_chart(chart, {kChartSize});
  EXPECT_GT(count(image, {0.9, 0.0, 0.0}).upper, 300);
}

TEST(LineChart, ReferenceLineIsGreyAndOutOfTheLegend) {
  LineChart chart = two_lines();
  chart.series.pop_back();
  chart.series[0].ys = {10, 10, 10};
  chart.reference_y = 0.0;
  const RgbImage image = render_line_chart(chart, {kChartSize});
  const ColourCount grey = count(image, {0.55, 0.55, 0.55}, 12);
  EXPECT_GT(grey.lower, 200);
  EXPECT_GT(grey.max_x - grey.min_x, kChartSize.width / 2);
}

TEST(LineChart, PngRoundTripKeepsTheImage) {
  TemporaryFolder folder("maxillo-chart-test");
  const auto png = folder / "chart.png";
  write_line_chart_png(two_lines(), png, {kChartSize});
  const RgbImage back = read_png(png);
  const RgbImage direct = render_line_chart(two_lines(), {kChartSize});
  EXPECT_EQ(back.width, kChartSize.width);
  EXPECT_EQ(back.height, kChartSize.height);
  EXPECT_EQ(back.pixels, direct.pixels);  // lossless and deterministic
}

TEST(LineChart, MalformedSeriesAreRefused) {
  LineChart chart = two_lines();
  chart.series[0].ys.pop_back();
  EXPECT_THROW(render_line_chart(chart, {kChartSize}), Error);
  chart.series.clear();
  EXPECT_THROW(render_line_chart(chart, {kChartSize}), Error);
}

}  // namespace
}  // namespace maxillo::render
