#include "sections/soft_tissue_section.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "casework/softtissue/profile_response.h"
#include "core/error.h"
#include "report/number_text.h"
#include "softtissue/boundary_move.h"
#include "softtissue/soft_tissue_model.h"

namespace maxillo::sections {
namespace {

using report::fixed;

std::string count_text(const records::SimulationSummary& s) {
  std::string text = std::to_string(s.prescribed_nodes) + " joined to moved bone, ";
  if (s.sliding_nodes) text += std::to_string(s.sliding_nodes) + " sliding on it, ";
  return text + std::to_string(s.fixed_nodes) + " fixed, " + std::to_string(s.free_nodes) + " free";
}

// How the tissue on the moved bone follows it (summaries before format 5: tied).
std::string bone_contact_text(const records::SimulationSummary& s) {
  if (s.bone_contact == "sliding")
    return "slides on it: the bone pushes it along its normal and leaves it free along its surface, as the "
           "subperiosteal dissection frees it" +
           (s.squeezed_nodes_freed > 0 ? "; " + std::to_string(s.squeezed_nodes_freed) +
                                             " nodes pinched between moved and unmoved bone are left free"
                                       : std::string());
  if (s.bone_contact == "sliding-in-cavities")
    return "tied to it on its outer surface, sliding on it inside its cavities";
  return "tied to it: moves with the bone";
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

// The tissues the model tells apart (summaries before format 4: one homogeneous tissue).
std::string nose_text(const records::SimulationSummary& s) {
  std::string text = "soft tissue, and the cartilaginous nose (" + std::to_string(s.nose_tets) + " tetrahedra) " +
                     fixed(s.nose_stiffness, 0) + " times stiffer";
  // From format 6 the moved bone does not carry the nose (casework/softtissue/nasal_cartilage.h).
  if (s.format_version >= 6)
    text += ", which follows the tissue, not the moved bone (" + std::to_string(s.nose_nodes_uncarried) +
            " of its nodes on the bone left free, as the septum is freed from the maxilla)";
  return text;
}

std::string tissues_text(const records::SimulationSummary& s) {
  std::string text = s.nose_tets == 0 ? "one homogeneous soft tissue" : nose_text(s);
  if (s.enclosed_voxels_left_out > 0)
    text += "; the soft tissue shut in by bone within the region (the brain's base) is left out";
  return text;
}

report::KeyValueBlock model_facts(const records::SimulationSummary& s, const std::string& title) {
  return {{
      {"Model", title + ", Poisson ratio " + fixed(s.poisson_ratio, 2)},
      {"Tissues", tissues_text(s)},
      {"Tissue on moved bone", bone_contact_text(s)},
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

// "pronasale (Prn)": the profile points as a surgeon reads them.
std::string profile_point_name(const std::string& label) {
  static const std::map<std::string, std::string> names{{"Prn", "nose tip, pronasale (Prn)"},
                                                        {"dorsum", "nasal dorsum, 8 mm above the tip"},
                                                        {"Sn", "subnasale (Sn)"},
                                                        {"Ls", "upper lip, labrale superius (Ls)"},
                                                        {"Li", "lower lip, labrale inferius (Li)"},
                                                        {"PogS", "soft-tissue pogonion (Pog')"}};
  const auto found = names.find(label);
  return found == names.end() ? label : found->second;
}

std::string band_text(const records::SimulationSummary::ProfilePoint& p) {
  if (!p.plausible_low && !p.plausible_high) return "none";
  return fixed(p.plausible_low.value_or(0), 2) + "-" + (p.plausible_high ? fixed(*p.plausible_high, 2) : "");
}

std::string verdict(const records::SimulationSummary::ProfilePoint& p) {
  if (!p.present) return "not on the skin";
  if (!p.plausible_low && !p.plausible_high) return "no band";
  const casework::PublishedResponse band{p.label, p.published, p.source, p.plausible_low, p.plausible_high};
  return casework::plausible(band, p.ratio) ? "plausible" : "OUTSIDE";
}

report::Table profile_table(const records::SimulationSummary::ProfileResponse& response) {
  report::Table table;
  table.columns = {{"profile point", 0.31},
                   {"forward (mm)", 0.13, report::Align::Right},
                   {"of the advance", 0.13, report::Align::Right},
                   {"published", 0.17},
                   {"plausible", 0.12, report::Align::Right},
                   {"", 0.14}};
  for (const auto& p : response.points)
    table.rows.push_back({profile_point_name(p.label), p.present ? fixed(p.forward_mm, 1) : "-",
                          p.present ? fixed(p.ratio, 2) : "-", p.published, band_text(p), verdict(p)});
  return table;
}

// The sources of the published figures, each once, in the table's order.
std::string sources_text(const records::SimulationSummary::ProfileResponse& response) {
  std::vector<std::string> sources;
  for (const auto& p : response.points)
    if (!p.source.empty() && std::find(sources.begin(), sources.end(), p.source) == sources.end())
      sources.push_back(p.source);
  std::string text;
  for (const auto& source : sources) text += (text.empty() ? "" : "; ") + source;
  return text;
}

// Whether the predicted profile moves as faces are measured to move after a Le Fort I
// advancement (issue 34): a surgeon sees at once whether the prediction is plausible.
void add_profile_response(const records::SimulationSummary::ProfileResponse& response, report::Section& section) {
  int outside = 0;
  for (const auto& p : response.points) outside += verdict(p) == "OUTSIDE";
  section.blocks.push_back(
      report::Paragraph{"Plausibility: how far the predicted profile moves forward for the maxilla's advancement of " +
                        fixed(response.advancement_mm, 1) + " mm (read at " + response.reference +
                        "), as a fraction of it, beside what published series of Le Fort I advancement measured. " +
                        (outside ? std::to_string(outside) + " point" + (outside > 1 ? "s lie" : " lies") +
                                       " outside the plausible band: read the predicted face there with care."
                                 : "Every point with a published band lies inside it.")});
  section.blocks.push_back(profile_table(response));
  std::string note = "Sources: " + sources_text(response) +
                     ". The bands are this program's, around the published means (docs/ARCHITECTURE.md). "
                     "Largest change of the displacement over the skin: " +
                     fixed(response.gradient_p999, 2) + " mm per mm (99.9th percentile of its edges), " +
                     fixed(response.gradient_max, 1) + " at most" +
                     (response.steepest_near.empty()
                          ? std::string(".")
                          : ", " + fixed(response.steepest_near_mm, 0) + " mm from " + response.steepest_near + ".");
  if (response.other_segments_moved)
    note += " The mandible or the chin moved as well; the series measured the maxilla moved alone.";
  section.blocks.push_back(report::Note{note});
}

// Where the model's region cuts tissue, and whether the move has died out there: a plane
// through tissue that still moves holds the face above or beside it in place (issue 34).
void add_boundary(const std::vector<records::SimulationSummary::BoundaryMove>& moves, report::Section& section) {
  std::string where;
  std::vector<std::string> still_moving;
  for (const auto& m : moves) {
    where += (where.empty() ? "" : ", ") + m.where + " " + fixed(m.largest_move_mm, 2) + " mm";
    if (m.largest_move_mm >= softtissue::kDecayedMoveMm) still_moving.push_back(m.where);
  }
  std::string text =
      "The model's edges, where its region cuts the tissue and holds it in place; the largest move "
      "within 5 mm inside each: " +
      where + ".";
  if (still_moving.empty()) {
    text += " The move has died out at every edge (below " + fixed(softtissue::kDecayedMoveMm, 1) + " mm).";
  } else {
    std::string list;
    for (size_t i = 0; i < still_moving.size(); ++i)
      list += (i == 0 ? "" : i + 1 == still_moving.size() ? " and " : ", ") + still_moving[i];
    text += " The tissue still moves at the edge" + std::string(still_moving.size() > 1 ? "s " : " ") + list +
            ": the prediction holds the face beyond " + (still_moving.size() > 1 ? "them" : "it") +
            " in place, which the real face may not do.";
  }
  section.blocks.push_back(report::Note{text});
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

// Where the model's cut planes lie, as the prediction named them (summaries before format 3,
// which kept no names, had the planes below the orbits, under the chin and in front of the ears).
std::string cut_planes_text(const records::SimulationSummary& s) {
  if (s.boundary_moves.empty()) return "below the orbits, under the chin, in front of the ears";
  std::string text;
  for (const auto& m : s.boundary_moves) text += (text.empty() ? "" : ", ") + m.where;
  return text;
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
      "(" +
      cut_planes_text(s) + ") stays in place."});
  section.blocks.push_back(model_facts(s, title));
  if (s.model_fallback) {
    const auto requested = softtissue::parse_model(s.model_fallback->requested);  // the reader has checked it
    section.blocks.push_back(report::Note{
        "The " + std::string(requested ? softtissue::model_title(*requested) : s.model_fallback->requested) +
        " was asked for and did not converge on this face (" + s.model_fallback->reason +
        "); the prediction shown is the " + title + "'s, which solves the same equations for small strains."});
  }
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
  if (s.profile_response) add_profile_response(*s.profile_response, section);
  if (!s.boundary_moves.empty()) add_boundary(s.boundary_moves, section);
  if (s.uncertainty) add_uncertainty(simulation, section);
  return section;
}

}  // namespace maxillo::sections
