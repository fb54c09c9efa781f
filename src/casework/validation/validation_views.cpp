#include "casework/validation/validation_views.h"

#include <array>
#include <cmath>

#include "core/error.h"
#include "mesh/plane_section.h"
#include "render/chart.h"
#include "render/view_files.h"

namespace maxillo::casework {
namespace {

constexpr int kValidationViewPixels = 900;
constexpr double kFramingMarginMm = 15;

// The faces whose three vertices satisfy `inside` (or, with inside == false, the others).
TriangleMesh faces_where(const TriangleMesh& mesh, const std::vector<double>& values, bool inside) {
  TriangleMesh part;
  part.vertices = mesh.vertices;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    bool defined = true;
    for (int k = 0; k < 3; ++k) defined = defined && !std::isnan(values[size_t(mesh.faces(f, k))]);
    if (defined == inside) kept.push_back(f);
  }
  part.faces.resize(Eigen::Index(kept.size()), 3);
  for (size_t i = 0; i < kept.size(); ++i) part.faces.row(Eigen::Index(i)) = mesh.faces.row(kept[i]);
  return part;
}

render::Bounds defined_bounds(const TriangleMesh& mesh, const std::vector<double>& values) {
  render::Bounds b;
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
    if (std::isnan(values[size_t(v)])) continue;
    b.min = b.min.cwiseMin(mesh.vertices.row(v).transpose());
    b.max = b.max.cwiseMax(mesh.vertices.row(v).transpose());
  }
  b.min.array() -= kFramingMarginMm;
  b.max.array() += kFramingMarginMm;
  return b;
}

// The longest run of consecutive polyline points inside the facial window, as (anterior, superior) millimetres from
// the origin.
render::ChartSeries facial_profile(const TriangleMesh& skin, const Eigen::Vector3d& origin,
                                   const AnatomicalFrame& frame, double top, double bottom, double back,
                                   const std::string& name, render::ColourRGB colour) {
  render::ChartSeries best{name, {}, {}, colour};
  for (const auto& line : plane_section(skin, origin, frame.left)) {
    render::ChartSeries run{name, {}, {}, colour};
    auto keep = [&] {
      if (run.xs.size() > best.xs.size()) best = run;
      run.xs.clear();
      run.ys.clear();
    };
    for (const auto& p : line) {
      const double a = (p - origin).dot(frame.anterior), s = (p - origin).dot(frame.superior);
      if (s <= top && s >= bottom && a >= back) {
        run.xs.push_back(a);
        run.ys.push_back(s);
      } else {
        keep();
      }
    }
    keep();
  }
  return best;
}

}  // namespace

std::vector<std::filesystem::path> render_error_maps(const TriangleMesh& predicted,
                                                     const std::vector<double>& distance_mm,
                                                     const AnatomicalFrame& frame, double range_mm,
                                                     const std::filesystem::path& folder) {
  if (std::all_of(distance_mm.begin(), distance_mm.end(), [](double d) { return std::isnan(d); }))
    throw Error(ErrorCode::kEmptyResult, "error map", "no predicted vertex has a distance to the post-operative skin");
  const TriangleMesh face = faces_where(predicted, distance_mm, true);
  const TriangleMesh rest = faces_where(predicted, distance_mm, false);
  render::VertexScalars error;
  error.values = distance_mm;
  for (double& d : error.values)
    if (std::isnan(d)) d = 0;  // vertices of the plain part only: never coloured
  error.range_min = -range_mm;
  error.range_max = range_mm;
  error.map = render::ColourMap::Diverging;
  error.title = "prediction - outcome (mm)";
  render::Scene scene;
  scene.meshes.push_back({&face, render::kSkinTone, 1.0, error});
  if (rest.face_count() > 0) scene.meshes.push_back({&rest, render::kSkinTone, 1.0, {}});
  render::RenderSettings settings;
  settings.size = {kValidationViewPixels, kValidationViewPixels};
  const std::array views{render::StandardView::Frontal, render::StandardView::Lateral, render::StandardView::Oblique};
  std::vector<std::filesystem::path> files;
  for (const auto& f : render::render_view_files(scene, frame, views, folder, "error-map-", settings,
                                                 defined_bounds(predicted, distance_mm)))
    files.push_back(f.png);
  return files;
}

void write_profile_overlay(const TriangleMesh& preop, const TriangleMesh& predicted, const TriangleMesh& actual,
                           const LandmarkSet& landmarks, const AnatomicalFrame& frame,
                           const std::filesystem::path& png) {
  const std::string subject = "profile overlay";
  const Eigen::Vector3d origin = require_landmark(landmarks, "Sn", subject);
  auto height = [&](const std::string& label) {
    return (require_landmark(landmarks, label, subject) - origin).dot(frame.superior);
  };
  const double top = height("N") + 15, bottom = height("Me") - 20;
  const double back = -45;  // mm behind subnasale: the face, not the back of the head
  render::ProfileChart chart;
  chart.title = "Mid-sagittal profiles";
  chart.curves.push_back(facial_profile(preop, origin, frame, top, bottom, back, "pre-operative", {0.55, 0.55, 0.55}));
  chart.curves.push_back(facial_profile(predicted, origin, frame, top, bottom, back, "predicted", {0.13, 0.40, 0.80}));
  chart.curves.push_back(
      facial_profile(actual, origin, frame, top, bottom, back, "post-operative", {0.85, 0.20, 0.15}));
  std::erase_if(chart.curves, [](const render::ChartSeries& c) { return c.xs.size() < 2; });
  if (chart.curves.empty())
    throw Error(ErrorCode::kEmptyResult, subject, "the mid-sagittal plane does not cut the faces");
  render::write_profile_chart_png(chart, png);
}

}  // namespace maxillo::casework
