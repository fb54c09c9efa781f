// The box plot of chart.h, drawn from lines on a vtkChartXY (vtkChartBox computes its own
// quartiles and whiskers at the extremes; the validation wants P5-P95 whiskers and the same
// percentile definition as its statistics).
#include <vtkAxis.h>
#include <vtkDoubleArray.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "render/chart.h"
#include "render/chart_canvas.h"
#include "render/chart_plots.h"

namespace maxillo::render {
namespace {

constexpr double kBoxHalfWidth = 0.3;  // in x units: groups stand 1 apart
constexpr double kWhiskerCapHalfWidth = 0.15;
constexpr float kMedianWidthPx = 4.5f;

void check(const BoxPlot& plot) {
  if (plot.groups.empty()) throw Error(ErrorCode::kBadValue, "box plot", "no groups to draw");
  for (const auto& g : plot.groups) {
    if (g.values.empty()) throw Error(ErrorCode::kBadValue, "box plot group " + g.name, "no values");
    for (double v : g.values)
      if (!std::isfinite(v)) throw Error(ErrorCode::kBadValue, "box plot group " + g.name, "a value is not finite");
  }
}

// Linear interpolation between order statistics ("type 7"), as validation::percentile.
double percentile_of_sorted(const std::vector<double>& sorted, double percent) {
  const double rank = percent / 100.0 * double(sorted.size() - 1);
  const auto below = std::size_t(std::floor(rank));
  const auto above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (rank - double(below)) * (sorted[above] - sorted[below]);
}

void draw_group(LinePlots& plots, double x, const BoxPlotSummary& s, ColourRGB colour) {
  const double l = x - kBoxHalfWidth, r = x + kBoxHalfWidth;
  add_polyline(plots, {l, r, r, l, l}, {s.p25, s.p25, s.p75, s.p75, s.p25}, colour, kLineWidthPx);
  add_polyline(plots, {l, r}, {s.p50, s.p50}, colour, kMedianWidthPx);
  for (const auto& [from, to] : {std::pair{s.p75, s.p95}, std::pair{s.p25, s.p5}}) {
    add_polyline(plots, {x, x}, {from, to}, colour, kLineWidthPx);
    add_polyline(plots, {x - kWhiskerCapHalfWidth, x + kWhiskerCapHalfWidth}, {to, to}, colour, kLineWidthPx);
  }
}

// Group names as the x axis's tick labels, at x = 1, 2, ...
void label_groups(vtkAxis& axis, const BoxPlot& plot) {
  auto positions = vtkSmartPointer<vtkDoubleArray>::New();
  auto labels = vtkSmartPointer<vtkStringArray>::New();
  for (std::size_t i = 0; i < plot.groups.size(); ++i) {
    positions->InsertNextValue(double(i + 1));
    labels->InsertNextValue(plot.groups[i].name);
  }
  axis.SetCustomTickPositions(positions, labels);
  axis.SetBehavior(vtkAxis::FIXED);
  axis.SetRange(1 - 2 * kBoxHalfWidth, double(plot.groups.size()) + 2 * kBoxHalfWidth);
  axis.SetGridVisible(false);
}

}  // namespace

BoxPlotSummary box_plot_summary(const std::vector<double>& values) {
  if (values.empty()) throw Error(ErrorCode::kBadValue, "box plot", "no values to summarise");
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  return {percentile_of_sorted(sorted, 5), percentile_of_sorted(sorted, 25), percentile_of_sorted(sorted, 50),
          percentile_of_sorted(sorted, 75), percentile_of_sorted(sorted, 95)};
}

ColourRGB box_colour(std::size_t index) { return chart_palette()[index % chart_palette().size()]; }

RgbImage render_box_plot(const BoxPlot& plot, const ChartSettings& settings) {
  check(plot);
  LinePlots plots;
  vtkChartXY& chart = *plots.chart;
  set_chart_title(chart, plot.title, settings);
  style_axis_text(chart, vtkAxis::BOTTOM, "", settings);
  style_axis_text(chart, vtkAxis::LEFT, plot.y_title, settings);
  chart.SetShowLegend(false);

  const double x_low = 1 - 2 * kBoxHalfWidth, x_high = double(plot.groups.size()) + 2 * kBoxHalfWidth;
  double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
  if (plot.reference_y) {  // first, so the boxes are drawn over it
    add_polyline(plots, {x_low, x_high}, {*plot.reference_y, *plot.reference_y}, kReferenceGrey, 1.5f);
    low = high = *plot.reference_y;
  }
  for (std::size_t i = 0; i < plot.groups.size(); ++i) {
    const BoxPlotSummary s = box_plot_summary(plot.groups[i].values);
    draw_group(plots, double(i + 1), s, box_colour(i));
    low = std::min(low, s.p5);
    high = std::max(high, s.p95);
  }
  label_groups(*chart.GetAxis(vtkAxis::BOTTOM), plot);
  const double pad = high > low ? kAxisMargin * (high - low) : 1.0;
  vtkAxis* y = chart.GetAxis(vtkAxis::LEFT);
  y->SetBehavior(vtkAxis::FIXED);
  y->SetRange(low - pad, high + pad);
  return render_chart_item(chart, settings);
}

void write_box_plot_png(const BoxPlot& plot, const std::filesystem::path& png, const ChartSettings& settings) {
  write_png(render_box_plot(plot, settings), png);
}

}  // namespace maxillo::render
