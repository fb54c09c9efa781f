#include "casework/softtissue/soft_tissue_views.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/render_views.h"
#include "render/view_files.h"

namespace maxillo::casework {
namespace {

constexpr std::array kViews = {render::StandardView::Frontal, render::StandardView::Lateral,
                               render::StandardView::Oblique};
constexpr int kSoftTissueViewPixels = 640;

render::Bounds union_bounds(const TriangleMesh& a, const TriangleMesh& b) {
  render::Scene both;
  both.meshes.push_back({&a, render::kSkinTone, 1.0, {}});
  both.meshes.push_back({&b, render::kSkinTone, 1.0, {}});
  return render::scene_bounds(both);
}

std::vector<std::filesystem::path> pngs(const std::vector<render::ViewFile>& files) {
  std::vector<std::filesystem::path> paths;
  for (const auto& f : files) paths.push_back(f.png);
  return paths;
}

}  // namespace

const std::vector<std::string>& soft_tissue_landmark_labels() {
  static const std::vector<std::string> labels{"NS", "Prn", "Sn", "Ls", "Li", "PogS"};
  return labels;
}

SoftTissueViewFiles render_soft_tissue_views(const TriangleMesh& skin_before, const SoftTissuePrediction& prediction,
                                             const AnatomicalFrame& frame, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  const auto bounds = union_bounds(skin_before, prediction.skin_after);  // the same cameras for all
  render::RenderSettings settings;
  settings.size = {kSoftTissueViewPixels, kSoftTissueViewPixels};

  SoftTissueViewFiles files;
  render::VertexScalars magnitude;
  magnitude.values.resize(size_t(prediction.skin_displacement.rows()));
  for (Eigen::Index v = 0; v < prediction.skin_displacement.rows(); ++v) {
    magnitude.values[size_t(v)] = prediction.skin_displacement.row(v).norm();
    files.max_displacement_mm = std::max(files.max_displacement_mm, magnitude.values[size_t(v)]);
  }
  magnitude.range_min = 0;
  // The colour scale ends at the 99.5th percentile: a few vertices inside the nostrils or at a
  // cut may move more, and would otherwise wash out the face's colours.
  std::vector<double> sorted = magnitude.values;
  const auto rank = size_t(0.995 * double(sorted.size() ? sorted.size() - 1 : 0));
  std::nth_element(sorted.begin(), sorted.begin() + long(rank), sorted.end());
  magnitude.range_max = std::max(1.0, std::ceil(sorted.empty() ? 0.0 : sorted[rank]));
  magnitude.map = render::ColourMap::Sequential;
  magnitude.title = "displacement (mm)";

  render::Scene before, after, displacement;
  before.meshes.push_back({&skin_before, render::kSkinTone, 1.0, {}});
  after.meshes.push_back({&prediction.skin_after, render::kSkinTone, 1.0, {}});
  displacement.meshes.push_back({&prediction.skin_after, render::kSkinTone, 1.0, magnitude});
  files.before =
      pngs(render::render_view_files(before, frame, kViews, folder, "soft-tissue-before-", settings, bounds));
  files.after = pngs(render::render_view_files(after, frame, kViews, folder, "soft-tissue-after-", settings, bounds));
  files.displacement = pngs(
      render::render_view_files(displacement, frame, kViews, folder, "soft-tissue-displacement-", settings, bounds));
  return files;
}

std::vector<std::filesystem::path> render_uncertainty_views(const TriangleMesh& skin_after,
                                                            const std::vector<double>& spread_mm,
                                                            const AnatomicalFrame& frame,
                                                            const std::filesystem::path& folder) {
  const std::array views{render::StandardView::Frontal, render::StandardView::Lateral};
  render::VertexScalars spread;
  spread.values = spread_mm;
  spread.range_min = 0;
  spread.range_max = std::max(0.5, std::ceil(2 * *std::max_element(spread_mm.begin(), spread_mm.end())) / 2);
  spread.map = render::ColourMap::Sequential;
  spread.title = "spread (mm)";
  render::Scene scene;
  scene.meshes.push_back({&skin_after, render::kSkinTone, 1.0, spread});
  render::RenderSettings settings;
  settings.size = {kSoftTissueViewPixels, kSoftTissueViewPixels};
  return pngs(render::render_view_files(scene, frame, views, folder, "soft-tissue-uncertainty-", settings));
}

}  // namespace maxillo::casework
