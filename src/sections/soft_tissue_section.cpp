#include "sections/soft_tissue_section.h"

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "report/number_text.h"
#include "softtissue/soft_tissue_model.h"

namespace maxillo::sections {
namespace {

using report::fixed;

std::string count_text(const records::SimulationSummary& s) {
  return std::to_string(s.prescribed_nodes) + " joined to moved bone, " + std::to_string(s.fixed_nodes) + " fixed, " +
         std::to_string(s.free_nodes) + " free";
}

report::Table landmark_table(const std::vector<records::SimulationSummary::LandmarkMove>& moves) {
  report::Table table;
  table.columns = {{"landmark", 0.25},
                   {"forward (mm)", 0.19, report::Align::Right},
                   {"up (mm)", 0.19, report::Align::Right},
                   {"left (mm)", 0.19, report::Align::Right},
                   {"total (mm)", 0.18, report::Align::Right}};
  for (const auto& m : moves)
    table.rows.push_back(
        {m.label, fixed(m.forward_mm, 1), fixed(m.up_mm, 1), fixed(m.left_mm, 1), fixed(m.total_mm, 1)});
  return table;
}

// The stored picture of this name; a summary without it is a damaged record.
std::filesystem::path picture(const records::StoredSimulation& simulation, const std::string& name) {
  const auto found = simulation.pictures.find(name);
  if (found == simulation.pictures.end())
    throw Error(ErrorCode::kArchiveCorrupt, simulation.source, "its picture " + name + " is not stored");
  return found->second;
}

// One row of pictures, "<prefix><view>" for each view, captioned "<what>, <view's title>".
report::ImageGrid picture_row(const records::StoredSimulation& simulation, const std::string& prefix,
                              const std::string& what, const std::vector<std::pair<std::string, std::string>>& views) {
  report::ImageGrid grid;
  grid.per_row = int(views.size());
  for (const auto& [view, title] : views)
    grid.figures.push_back({picture(simulation, prefix + view), what + ", " + title});
  return grid;
}

const std::vector<std::pair<std::string, std::string>> kThreeViews{
    {"frontal", "frontal"}, {"lateral", "right lateral"}, {"oblique", "oblique"}};

report::KeyValueBlock model_facts(const records::SimulationSummary& s, const std::string& title) {
  return {{
      {"Model", title + ", Poisson ratio " + fixed(s.poisson_ratio, 2)},
      {"Tetrahedral mesh", std::to_string(s.tetrahedra) + " tetrahedra, " + std::to_string(s.nodes) +
                               " nodes (cell size " + fixed(s.cell_size_mm, 1) + " mm)"},
      {"Element quality", "smallest dihedral angle " + fixed(s.min_dihedral_deg, 1) + "°, aspect ratio mean " +
                              fixed(s.mean_aspect_ratio, 2) + ", max " + fixed(s.max_aspect_ratio, 1)},
      {"Nodes", count_text(s)},
      {"Largest skin displacement", fixed(s.max_skin_displacement_mm, 1) + " mm"},
      {"Time", "mesh " + fixed(s.seconds.meshing, 1) + " s, solve " + fixed(s.seconds.solve, 2) + " s (" +
                   std::to_string(s.iterations) + " iterations), mapping to the skin " + fixed(s.seconds.mapping, 2) +
                   " s"},
  }};
}

void add_uncertainty(const records::StoredSimulation& simulation, report::Section& section) {
  const auto& band = *simulation.summary.uncertainty;
  section.blocks.push_back(
      report::Paragraph{"Uncertainty band: how far the predicted skin moves when the model "
                        "or the Poisson ratio changes (largest distance from the runs' mean)."});
  section.blocks.push_back(picture_row(simulation, "soft-tissue-uncertainty-", "Uncertainty band",
                                       {{"frontal", "frontal"}, {"lateral", "right lateral"}}));
  section.blocks.push_back(
      report::Note{"Uncertainty band: across " + std::to_string(band.runs.size()) +
                   " runs (other models, Poisson ratio 0.45-0.49) the predicted skin position spreads by up to " +
                   std::to_string(band.max_mm).substr(0, 4) + " mm (95th percentile " +
                   std::to_string(band.p95_mm).substr(0, 4) + " mm) from their mean."});
}

}  // namespace

report::Section soft_tissue_section(const records::StoredSimulation& simulation) {
  const records::SimulationSummary& s = simulation.summary;
  const auto model = softtissue::parse_model(s.model);  // the reader has checked the name
  const std::string title(model ? softtissue::model_title(*model) : s.model);
  report::Section section{"soft_tissue", {}};
  section.blocks.push_back(report::Paragraph{
      "Predicted face for the planned bone moves (" + s.plan_text + "), computed with the " + title +
      " on a tetrahedral model of the facial soft tissue. "
      "Tissue touching a moved bone segment follows it; tissue on unmoved bone and on the model's cut planes "
      "(below the orbits, under the chin, in front of the ears) stays in place."});
  section.blocks.push_back(model_facts(s, title));
  if (s.over_tet_budget)
    section.blocks.push_back(report::Note{"The tetrahedral mesh is over its budget: " + std::to_string(s.tetrahedra) +
                                          " tetrahedra against at most " + std::to_string(s.tet_budget) +
                                          " asked for, after " + std::to_string(s.meshing_attempts) +
                                          " meshings up to a cell size of " + fixed(s.cell_size_mm, 1) +
                                          " mm. The prediction used it as it is; it took longer than planned."});
  section.blocks.push_back(picture_row(simulation, "soft-tissue-before-", "Pre-operative", kThreeViews));
  section.blocks.push_back(picture_row(simulation, "soft-tissue-after-", "Predicted", kThreeViews));
  section.blocks.push_back(picture_row(simulation, "soft-tissue-displacement-", "Displacement", kThreeViews));
  if (!s.soft_landmarks.empty()) {
    section.blocks.push_back(
        report::Paragraph{"Predicted displacement of the soft tissue landmarks "
                          "(forward, up and to the patient's left in the anatomical frame):"});
    section.blocks.push_back(landmark_table(s.soft_landmarks));
  }
  if (s.uncertainty) add_uncertainty(simulation, section);
  return section;
}

}  // namespace maxillo::sections
