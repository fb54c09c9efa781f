// The line chart of chart.h: one vtkPlotLine per series on a vtkChartXY, each series in its own
// two-column vtkTable because the series need not share x values.
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "render/chart.h"
#include "render/chart_canvas.h"
#include "render/chart_plots.h"

namespace maxillo::render {
namespace {

constexpr float kMarkerSizePx = 7.0f;

void check(const LineChart& chart) { check_series(chart.series, "line chart"); }

// Keeps the tables alive as long as the chart that plots them.
struct Plotted {
  vtkSmartPointer<vtkChartXY> chart = vtkSmartPointer<vtkChartXY>::New();
  std::vector<vtkSmartPointer<vtkTable>> tables;
};

vtkPlot* add_line(Plotted& plotted, const std::vector<double>& xs, const std::vector<double>& ys, ColourRGB colour,
                  float width) {
  plotted.tables.push_back(xy_table(xs, ys));
  vtkPlot* plot = plotted.chart->AddPlot(vtkChart::LINE);
  plot->SetInputData(plotted.tables.back(), 0, 1);
  plot->SetColor(colour.r, colour.g, colour.b);
  plot->SetWidth(width);
  return plot;
}

std::pair<double, double> range_of(const LineChart& chart, bool along_x) {
  double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
  for (const auto& s : chart.series)
    for (double v : along_x ? s.xs : s.ys) low = std::min(low, v), high = std::max(high, v);
  if (!along_x && chart.reference_y) low = std::min(low, *chart.reference_y), high = std::max(high, *chart.reference_y);
  return {low, high};
}

// The data range widened by kAxisMargin of its span on each side (1 unit for a single value), so
// no line runs on an axis or the frame.
void set_padded_range(vtkChartXY& chart, int axis_id, std::pair<double, double> range) {
  auto [low, high] = range;
  const double pad = high > low ? kAxisMargin * (high - low) : 1.0;
  vtkAxis* axis = chart.GetAxis(axis_id);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(low - pad, high + pad);
}

void style_legend(vtkChartXY& chart, const ChartSettings& settings) {
  chart.SetShowLegend(true);
  vtkChartLegend* legend = chart.GetLegend();
  legend->SetLabelSize(settings.font_size * 4 / 5);
  legend->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  legend->SetVerticalAlignment(vtkChartLegend::TOP);
}

}  // namespace

const std::vector<ColourRGB>& chart_palette() {
  // Tableau 10 without its grey, plus a dark blue: distinct hues, all far from white and grey.
  static const std::vector<ColourRGB> palette = {{0.122, 0.467, 0.706}, {1.000, 0.498, 0.055}, {0.173, 0.627, 0.173},
                                                 {0.839, 0.153, 0.157}, {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294},
                                                 {0.890, 0.467, 0.761}, {0.737, 0.741, 0.133}, {0.090, 0.745, 0.812},
                                                 {0.100, 0.100, 0.500}};
  return palette;
}

ColourRGB series_colour(const LineChart& chart, std::size_t index) {
  const auto& s = chart.series.at(index);
  return s.colour ? *s.colour : chart_palette()[index % chart_palette().size()];
}

RgbImage render_line_chart(const LineChart& chart, const ChartSettings& settings) {
  check(chart);
  Plotted plotted;
  vtkChartXY& xy = *plotted.chart;
  if (!chart.title.empty()) {
    xy.SetTitle(chart.title);
    xy.GetTitleProperties()->SetFontSize(settings.font_size);
    xy.GetTitleProperties()->SetColor(0, 0, 0);
  }
  style_axis_text(xy, vtkAxis::BOTTOM, chart.x_title, settings);
  style_axis_text(xy, vtkAxis::LEFT, chart.y_title, settings);

  if (chart.reference_y) {  // first, so the series are drawn over it
    auto [low, high] = range_of(chart, true);
    vtkPlot* line = add_line(plotted, {low, high}, {*chart.reference_y, *chart.reference_y}, kReferenceGrey, 1.5f);
    line->SetLegendVisibility(false);
    if (auto* points = vtkPlotPoints::SafeDownCast(line)) points->SetMarkerStyle(vtkPlotPoints::NONE);
  }
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const auto& s = chart.series[i];
    vtkPlot* line = add_line(plotted, s.xs, s.ys, series_colour(chart, i), kLineWidthPx);
    line->SetLabel(s.name);
    if (auto* points = vtkPlotPoints::SafeDownCast(line)) {
      points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
      points->SetMarkerSize(kMarkerSizePx);
    }
  }
  set_padded_range(xy, vtkAxis::BOTTOM, range_of(chart, true));
  set_padded_range(xy, vtkAxis::LEFT, range_of(chart, false));
  style_legend(xy, settings);
  return render_chart_item(xy, settings);
}

void write_line_chart_png(const LineChart& chart, const std::filesystem::path& png, const ChartSettings& settings) {
  write_png(render_line_chart(chart, settings), png);
}

}  // namespace maxillo::render
