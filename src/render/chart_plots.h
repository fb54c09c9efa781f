#pragma once
// Private to src/render: polylines on a vtkChartXY for chart kinds drawn from lines (box plots,
// profiles). Never include this from another module (it carries VTK types).
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>

#include <vector>

#include "render/chart.h"

namespace maxillo::render {

// A chart with the tables its plots read, kept alive together.
struct LinePlots {
  vtkSmartPointer<vtkChartXY> chart = vtkSmartPointer<vtkChartXY>::New();
  std::vector<vtkSmartPointer<vtkTable>> tables;
};

// Error(kBadValue) naming `what` (e.g. "line chart") when there is no series, or a series is
// empty or has xs and ys of different lengths.
void check_series(const std::vector<ChartSeries>& series, const std::string& what);

// A two-column table ("x", "y") of the points, as VTK's plots read them.
vtkSmartPointer<vtkTable> xy_table(const std::vector<double>& xs, const std::vector<double>& ys);

// A polyline through (xs[i], ys[i]) in `colour`, `width` pixels wide, without markers and out of
// the legend (give it a label and SetLegendVisibility(true) to list it).
vtkPlot* add_polyline(LinePlots& plots, const std::vector<double>& xs, const std::vector<double>& ys, ColourRGB colour,
                      float width);

// Title (if any) in the chart's font size, black.
void set_chart_title(vtkChartXY& chart, const std::string& title, const ChartSettings& settings);

}  // namespace maxillo::render
