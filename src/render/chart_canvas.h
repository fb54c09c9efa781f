#pragma once
// Private to src/render: the off-screen step every chart kind shares. A vtkChart (XY, box, ...)
// is placed in a vtkContextActor filling a renderer of the OSMesa window, rendered once and read
// back. Never include this from another module (it carries VTK types).
#include <vtkChart.h>

#include "render/chart.h"

namespace maxillo::render {

// The style every chart kind shares: line width, the grey of reference lines and bands, and the
// margin around the data (a fraction of its span on each side, so no line runs on the frame).
inline constexpr float kLineWidthPx = 2.5f;
inline constexpr ColourRGB kReferenceGrey{0.55, 0.55, 0.55};
inline constexpr double kAxisMargin = 0.06;

// Renders `chart` (already filled with plots and axes) at settings.size on settings.background.
// Throws Error(RenderFailed) when the image read back has the wrong size.
RgbImage render_chart_item(vtkChart& chart, const ChartSettings& settings);

// Axis titles and tick labels in the chart's font size, black.
void style_axis_text(vtkChart& chart, int axis, const std::string& title, const ChartSettings& settings);

}  // namespace maxillo::render
