// The profile chart of chart.h: curves in millimetres drawn at one scale on both axes, so a
// profile keeps its true shape. The axes are pinned to a fixed pixel rectangle
// (vtkChart::AXES_TO_RECT) and the data ranges are widened until both axes show the same mm per pixel.
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkRect.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "core/error.h"
#include "render/chart.h"
#include "render/chart_canvas.h"
#include "render/chart_plots.h"

namespace maxillo::render {
namespace {

void check(const ProfileChart& chart) { check_series(chart.curves, "profile chart"); }

struct Range {
  double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
  void extend(double v) { low = std::min(low, v), high = std::max(high, v); }
  double centre() const { return (low + high) / 2; }
  double span() const { return high - low; }
};

// The pixel rectangle the axes span: margins for tick labels and titles on the left and bottom,
// for the title on top, in proportion to the font size.
vtkRectf plot_area(const ChartSettings& settings) {
  const float f = float(settings.font_size);
  const float left = 5.0f * f, bottom = 4.0f * f, top = 2.5f * f, right = 1.5f * f;
  return vtkRectf(left, bottom, std::max(10.0f, float(settings.size.width) - left - right),
                  std::max(10.0f, float(settings.size.height) - bottom - top));
}

}  // namespace

ColourRGB curve_colour(const ProfileChart& chart, std::size_t index) {
  const auto& c = chart.curves.at(index);
  return c.colour ? *c.colour : chart_palette()[index % chart_palette().size()];
}

RgbImage render_profile_chart(const ProfileChart& chart, const ChartSettings& settings) {
  check(chart);
  LinePlots plots;
  vtkChartXY& xy = *plots.chart;
  set_chart_title(xy, chart.title, settings);
  style_axis_text(xy, vtkAxis::BOTTOM, "anterior-posterior (mm)", settings);
  style_axis_text(xy, vtkAxis::LEFT, "height (mm)", settings);

  Range xs, ys;
  for (std::size_t i = 0; i < chart.curves.size(); ++i) {
    const auto& c = chart.curves[i];
    vtkPlot* line = add_polyline(plots, c.xs, c.ys, curve_colour(chart, i), kLineWidthPx);
    line->SetLabel(c.name);
    line->SetLegendVisibility(true);
    for (double v : c.xs) xs.extend(v);
    for (double v : c.ys) ys.extend(v);
  }

  // One scale: the larger of the two mm-per-pixel needs, each range widened about its centre.
  const vtkRectf area = plot_area(settings);
  xy.SetLayoutStrategy(vtkChart::AXES_TO_RECT);
  xy.SetSize(area);
  const double x_span = std::max(xs.span(), 1.0) * (1 + 2 * kAxisMargin);
  const double y_span = std::max(ys.span(), 1.0) * (1 + 2 * kAxisMargin);
  const double mm_per_px = std::max(x_span / area.GetWidth(), y_span / area.GetHeight());
  const double half_width = mm_per_px * area.GetWidth() / 2, half_height = mm_per_px * area.GetHeight() / 2;
  for (auto [axis_id, centre, half] : {std::tuple{int(vtkAxis::BOTTOM), xs.centre(), half_width},
                                       std::tuple{int(vtkAxis::LEFT), ys.centre(), half_height}}) {
    vtkAxis* axis = xy.GetAxis(axis_id);
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetRange(centre - half, centre + half);
  }

  xy.SetShowLegend(true);
  vtkChartLegend* legend = xy.GetLegend();
  legend->SetLabelSize(settings.font_size * 4 / 5);
  legend->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  legend->SetVerticalAlignment(vtkChartLegend::TOP);
  return render_chart_item(xy, settings);
}

void write_profile_chart_png(const ProfileChart& chart, const std::filesystem::path& png,
                             const ChartSettings& settings) {
  write_png(render_profile_chart(chart, settings), png);
}

}  // namespace maxillo::render
