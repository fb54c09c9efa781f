#pragma once
// Charts as plain data, rendered off-screen (VTK's 2D charts on the OSMesa context) into RGB
// images and PNG files for reports: line charts (e.g. the Wits appraisal over months, one line per
// patient, the source's Fig. 10), box plots and equal-scale profiles (the validation). Each kind
// has its own data struct and render function and shares the off-screen step (chart_canvas.h).
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
  std::string name;        // legend entry
  std::vector<double> xs;  // same length as ys; at least one point
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

// A box plot per group (e.g. one per case or per face subregion), the groups side by side at
// x = 1, 2, ... and labelled by name on the x axis. The box spans P25-P75 with a thick line at the
// median (P50), the whiskers P5-P95; percentiles interpolate linearly between order statistics
// ("type 7", as validation::percentile). Group i is drawn in chart_palette()[i % size]; no legend.
struct BoxPlotGroup {
  std::string name;
  std::vector<double> values;  // at least one, finite
};
struct BoxPlot {
  std::string title, y_title;
  std::vector<BoxPlotGroup> groups;
  std::optional<double> reference_y;  // a thin grey horizontal line (e.g. 0 mm error)
};
struct BoxPlotSummary {
  double p5 = 0, p25 = 0, p50 = 0, p75 = 0, p95 = 0;
};
// What a group's box shows. Throws Error(BadValue) for no values.
BoxPlotSummary box_plot_summary(const std::vector<double>& values);
ColourRGB box_colour(std::size_t group_index);
// Throws Error(BadValue) for no groups, a group without values or a value that is not finite.
RgbImage render_box_plot(const BoxPlot& plot, const ChartSettings& settings = {});
void write_box_plot_png(const BoxPlot& plot, const std::filesystem::path& png, const ChartSettings& settings = {});

// Profiles (e.g. the mid-sagittal predicted and actual skin, from mesh/plane_section.h): curves
// with xs = anterior-posterior mm and ys = height mm, drawn with the SAME mm per pixel on both
// axes (the data ranges are widened to fit), so a profile keeps its true shape. Legend at the top
// right; curve colours as for a line chart's series.
struct ProfileChart {
  std::string title;
  std::vector<ChartSeries> curves;
};
ColourRGB curve_colour(const ProfileChart& chart, std::size_t index);
// Throws Error(BadValue) for no curves, or a curve that is empty or whose xs and ys differ in length.
RgbImage render_profile_chart(const ProfileChart& chart, const ChartSettings& settings = {});
void write_profile_chart_png(const ProfileChart& chart, const std::filesystem::path& png,
                             const ChartSettings& settings = {});

}  // namespace maxillo::render
