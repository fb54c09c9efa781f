#include "pipeline/soft_tissue_section.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "render/render_views.h"
#include "render/view_files.h"

#include "report/number_text.h"

namespace maxillo::pipeline {
namespace {

constexpr std::array kViews = {render::StandardView::Frontal, render::StandardView::Lateral,
                               render::StandardView::Oblique};
constexpr int kImagePixels = 640;

using report::fixed;

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

std::string count_text(const softtissue::BoundaryConditions& bc) {
  using softtissue::NodeConstraint;
  return std::to_string(softtissue::count_nodes(bc, NodeConstraint::kPrescribed)) + " joined to moved bone, " +
         std::to_string(softtissue::count_nodes(bc, NodeConstraint::kFixed)) + " fixed, " +
         std::to_string(softtissue::count_nodes(bc, NodeConstraint::kFree)) + " free";
}

report::Table landmark_table(const SoftTissuePrediction& prediction, const AnatomicalFrame& frame,
                             const LandmarkSet& landmarks) {
  report::Table table;
  table.columns = {{"landmark", 0.25},
                   {"forward (mm)", 0.19, report::Align::Right},
                   {"up (mm)", 0.19, report::Align::Right},
                   {"left (mm)", 0.19, report::Align::Right},
                   {"total (mm)", 0.18, report::Align::Right}};
  VertexMatrix points(Eigen::Index(landmarks.size()), 3);
  for (size_t i = 0; i < landmarks.size(); ++i) points.row(Eigen::Index(i)) = landmarks[i].position.transpose();
  const auto u = displacement_at(prediction, points, 4.0);
  for (size_t i = 0; i < landmarks.size(); ++i) {
    const Eigen::Vector3d d = u.row(Eigen::Index(i)).transpose();
    table.rows.push_back({landmarks[i].label, fixed(d.dot(frame.anterior), 1), fixed(d.dot(frame.superior), 1),
                          fixed(d.dot(frame.left), 1), fixed(d.norm(), 1)});
  }
  return table;
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
  settings.size = {kImagePixels, kImagePixels};

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

report::ImageGrid render_uncertainty_views(const TriangleMesh& skin_after, const std::vector<double>& spread_mm,
                                           const AnatomicalFrame& frame, const std::filesystem::path& folder) {
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
  settings.size = {kImagePixels, kImagePixels};
  const auto files = render::render_view_files(scene, frame, views, folder, "soft-tissue-uncertainty-", settings);
  report::ImageGrid grid;
  grid.per_row = 2;
  const std::array<std::string, 2> names{"frontal", "right lateral"};
  for (size_t v = 0; v < files.size(); ++v) grid.figures.push_back({files[v].png, "Uncertainty band, " + names[v]});
  return grid;
}

report::Section soft_tissue_section(const SoftTissuePrediction& prediction, const SoftTissueViewFiles& views,
                                    const AnatomicalFrame& frame, const SoftTissueSummary& summary) {
  report::Section section{"soft_tissue", {}};
  section.blocks.push_back(report::Paragraph{
      "Predicted face for the planned bone moves (" + summary.plan_text + "), computed with the " +
      std::string(model_title(summary.options.model)) +
      " on a tetrahedral model of the facial soft tissue. "
      "Tissue touching a moved bone segment follows it; tissue on unmoved bone and on the model's cut planes "
      "(below the orbits, under the chin, in front of the ears) stays in place."});
  report::KeyValueBlock facts{{
      {"Model",
       std::string(model_title(summary.options.model)) + ", Poisson ratio " + fixed(summary.options.poisson_ratio, 2)},
      {"Tetrahedral mesh", std::to_string(prediction.mesh.tet_count()) + " tetrahedra, " +
                               std::to_string(prediction.mesh.node_count()) + " nodes (cell size " +
                               fixed(prediction.meshing.cell_size_mm, 1) + " mm)"},
      {"Element quality", "smallest dihedral angle " + fixed(prediction.quality.min_dihedral_deg, 1) +
                              "°, aspect ratio mean " + fixed(prediction.quality.mean_aspect_ratio, 2) + ", max " +
                              fixed(prediction.quality.max_aspect_ratio, 1)},
      {"Nodes", count_text(prediction.bc)},
      {"Largest skin displacement", fixed(views.max_displacement_mm, 1) + " mm"},
      {"Time", "mesh " + fixed(prediction.seconds.meshing, 1) + " s, solve " + fixed(prediction.seconds.solve, 2) +
                   " s (" + std::to_string(prediction.iterations) + " iterations), mapping to the skin " +
                   fixed(prediction.seconds.mapping, 2) + " s"},
  }};
  section.blocks.push_back(facts);
  if (prediction.meshing.over_budget(prediction.mesh))
    section.blocks.push_back(
        report::Note{"The tetrahedral mesh is over its budget: " + std::to_string(prediction.mesh.tet_count()) +
                     " tetrahedra against at most " + std::to_string(prediction.meshing.tet_budget) +
                     " asked for, after " + std::to_string(prediction.meshing.attempts) +
                     " meshings up to a cell size of " + fixed(prediction.meshing.cell_size_mm, 1) +
                     " mm. The prediction used it as it is; it took longer than planned."});
  auto grid = [](const std::vector<std::filesystem::path>& files, const std::string& what) {
    report::ImageGrid g;
    g.per_row = 3;
    const std::array<std::string, 3> names{"frontal", "right lateral", "oblique"};
    for (size_t v = 0; v < files.size(); ++v) g.figures.push_back({files[v], what + ", " + names[v]});
    return g;
  };
  section.blocks.push_back(grid(views.before, "Pre-operative"));
  section.blocks.push_back(grid(views.after, "Predicted"));
  section.blocks.push_back(grid(views.displacement, "Displacement"));
  if (!summary.soft_landmarks.empty()) {
    section.blocks.push_back(
        report::Paragraph{"Predicted displacement of the soft tissue landmarks "
                          "(forward, up and to the patient's left in the anatomical frame):"});
    section.blocks.push_back(landmark_table(prediction, frame, summary.soft_landmarks));
  }
  return section;
}

}  // namespace maxillo::pipeline
