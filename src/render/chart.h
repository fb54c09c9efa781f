#pragma once
// Charts as plain data, rendered off-screen (VTK's 2D charts on the OSMesa context) into RGB
// images and PNG files for reports. A line chart today (e.g. the Wits appraisal over months, one
// line per patient, the source's Fig. 10); other chart kinds (a box plot for the validation)
// add their own data struct and render function next to it and share the off-screen step
// (chart_canvas.h).
//
// Look: white background, black axes with titles, a legend at the top right, one distinct
// colour per series (chart_palette), lines 2.5 px wide with round markers at the data points.
// Rendering is deterministic: the same chart and size give the same pixels.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/offscreen_context.h"
#include "render/render_views.h"
#include "render/scene.h"

namespace maxillo::render {

struct ChartSeries {
  std::string name;          // legend entry
  std::vector<double> xs;    // same length as ys; at least one point
  std::vector<double> ys;
  std::optional<ColourRGB> colour;  // default: chart_palette()[index % size]
};

struct LineChart {
  std::string title;    // "" = none
  std::string x_title;  // axis titles, with units
  std::string y_title;
  std::vector<ChartSeries> series;
  std::optional<double> reference_y;  // a thin grey horizontal line (e.g. Wits = 0 mm, the norm)
};

struct ChartSettings {
  ImageSize size{1200, 750};
  ColourRGB background{1.0, 1.0, 1.0};
  int font_size = 20;  // axis titles and legend, in pixels; tick labels are 0.8 of it
};

// Ten distinct, saturated colours (none close to white, grey or black), in the order series get them.
const std::vector<ColourRGB>& chart_palette();
// The colour series `index` of `chart` is drawn in.
ColourRGB series_colour(const LineChart& chart, std::size_t index);

// Throws Error(BadValue) for a series whose xs and ys differ in length or that is empty, or a
// chart without series; Error(RenderFailed) when rendering fails.
RgbImage render_line_chart(const LineChart& chart, const ChartSettings& settings = {});
// The same, written as a PNG (atomically).
void write_line_chart_png(const LineChart& chart, const std::filesystem::path& png, const ChartSettings& settings = {});

}  // namespace maxillo::render
