#pragma once
// Private to src/render: the off-screen step every chart kind shares. A vtkChart (XY, box, ...)
// is placed in a vtkContextActor filling a renderer of the OSMesa window, rendered once and read
// back. Never include this from another module (it carries VTK types).
#include <vtkChart.h>

#include "render/chart.h"

namespace maxillo::render {

// Renders `chart` (already filled with plots and axes) at settings.size on settings.background.
// Throws Error(RenderFailed) when the image read back has the wrong size.
RgbImage render_chart_item(vtkChart& chart, const ChartSettings& settings);

// Axis titles and tick labels in the chart's font size, black.
void style_axis_text(vtkChart& chart, int axis, const std::string& title, const ChartSettings& settings);

}  // namespace maxillo::render
