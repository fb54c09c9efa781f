#include "sections/soft_tissue_section.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "report/number_text.h"

namespace maxillo::sections {
namespace {

using report::fixed;

std::string count_text(const softtissue::BoundaryConditions& bc) {
  using softtissue::NodeConstraint;
  return std::to_string(softtissue::count_nodes(bc, NodeConstraint::kPrescribed)) + " joined to moved bone, " +
         std::to_string(softtissue::count_nodes(bc, NodeConstraint::kFixed)) + " fixed, " +
         std::to_string(softtissue::count_nodes(bc, NodeConstraint::kFree)) + " free";
}

report::Table landmark_table(const casework::SoftTissuePrediction& prediction, const AnatomicalFrame& frame,
                             const LandmarkSet& landmarks) {
  report::Table table;
  table.columns = {{"landmark", 0.25},
                   {"forward (mm)", 0.19, report::Align::Right},
                   {"up (mm)", 0.19, report::Align::Right},
                   {"left (mm)", 0.19, report::Align::Right},
                   {"total (mm)", 0.18, report::Align::Right}};
  VertexMatrix points(Eigen::Index(landmarks.size()), 3);
  for (size_t i = 0; i < landmarks.size(); ++i) points.row(Eigen::Index(i)) = landmarks[i].position.transpose();
  const auto u = casework::displacement_at(prediction, points, 4.0);
  for (size_t i = 0; i < landmarks.size(); ++i) {
    const Eigen::Vector3d d = u.row(Eigen::Index(i)).transpose();
    table.rows.push_back({landmarks[i].label, fixed(d.dot(frame.anterior), 1), fixed(d.dot(frame.superior), 1),
                          fixed(d.dot(frame.left), 1), fixed(d.norm(), 1)});
  }
  return table;
}

}  // namespace

report::Section soft_tissue_section(const casework::SoftTissuePrediction& prediction,
                                    const casework::SoftTissueViewFiles& views, const AnatomicalFrame& frame,
                                    const SoftTissueSummary& summary) {
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

report::Section soft_tissue_section(const casework::SimulationResult& result,
                                    const casework::SimulationRequest& request) {
  const SoftTissueSummary summary{request.plan_text.empty() ? request.plan.description : request.plan_text,
                                  request.options, result.soft_landmarks};
  report::Section section = soft_tissue_section(result.prediction, result.views, result.frame, summary);
  if (!result.uncertainty) return section;
  const auto& band = *result.uncertainty;
  section.blocks.push_back(
      report::Paragraph{"Uncertainty band: how far the predicted skin moves when the model "
                        "or the Poisson ratio changes (largest distance from the runs' mean)."});
  report::ImageGrid grid;
  grid.per_row = 2;
  const std::array<std::string, 2> names{"frontal", "right lateral"};
  for (size_t v = 0; v < result.uncertainty_views.size() && v < names.size(); ++v)
    grid.figures.push_back({result.uncertainty_views[v], "Uncertainty band, " + names[v]});
  section.blocks.push_back(grid);
  section.blocks.push_back(
      report::Note{"Uncertainty band: across " + std::to_string(band.runs.size()) +
                   " runs (other models, Poisson ratio 0.45-0.49) the predicted skin position spreads by up to " +
                   std::to_string(band.max_mm).substr(0, 4) + " mm (95th percentile " +
                   std::to_string(band.p95_mm).substr(0, 4) + " mm) from their mean."});
  return section;
}

}  // namespace maxillo::sections
