#include "render/chart_plots.h"

#include <vtkDoubleArray.h>
#include <vtkPlotPoints.h>
#include <vtkTextProperty.h>

#include <algorithm>

#include "core/error.h"

namespace maxillo::render {

void check_series(const std::vector<ChartSeries>& series, const std::string& what) {
  if (series.empty()) throw Error(ErrorCode::kBadValue, what, "nothing to draw");
  for (const auto& s : series) {
    if (s.xs.size() != s.ys.size())
      throw Error(ErrorCode::kBadValue, what + " " + s.name, "xs and ys differ in length");
    if (s.xs.empty()) throw Error(ErrorCode::kBadValue, what + " " + s.name, "no points");
  }
}

vtkSmartPointer<vtkTable> xy_table(const std::vector<double>& xs, const std::vector<double>& ys) {
  auto x = vtkSmartPointer<vtkDoubleArray>::New();
  x->SetName("x");
  auto y = vtkSmartPointer<vtkDoubleArray>::New();
  y->SetName("y");
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(x);
  table->AddColumn(y);
  table->SetNumberOfRows(static_cast<vtkIdType>(std::min(xs.size(), ys.size())));
  for (std::size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
    table->SetValue(static_cast<vtkIdType>(i), 0, xs[i]);
    table->SetValue(static_cast<vtkIdType>(i), 1, ys[i]);
  }
  return table;
}

vtkPlot* add_polyline(LinePlots& plots, const std::vector<double>& xs, const std::vector<double>& ys, ColourRGB colour,
                      float width) {
  auto table = xy_table(xs, ys);
  plots.tables.push_back(table);

  vtkPlot* plot = plots.chart->AddPlot(vtkChart::LINE);
  plot->SetInputData(table, 0, 1);
  plot->SetColor(colour.r, colour.g, colour.b);
  plot->SetWidth(width);
  plot->SetLegendVisibility(false);
  if (auto* points = vtkPlotPoints::SafeDownCast(plot)) points->SetMarkerStyle(vtkPlotPoints::NONE);
  return plot;
}

void set_chart_title(vtkChartXY& chart, const std::string& title, const ChartSettings& settings) {
  if (title.empty()) return;
  chart.SetTitle(title);
  chart.GetTitleProperties()->SetFontSize(settings.font_size);
  chart.GetTitleProperties()->SetColor(0, 0, 0);
}

}  // namespace maxillo::render
