// The soft-tissue section is built from the stored prediction alone: its facts, the over-budget
// note with the numbers, the landmark table, the uncertainty band, and a loud error when a
// picture the summary needs is not stored.
#include "sections/soft_tissue_section.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "support/error_of.h"
#include "support/report_blocks.h"

namespace maxillo::sections {
namespace {

using testing::blocks_of;
using testing::notes_of;

records::StoredSimulation stored_prediction(int tetrahedra, int tet_budget) {
  records::StoredSimulation stored;
  stored.source = "artefact 9 (simulation)";
  records::SimulationSummary& s = stored.summary;
  s.plan_text = "maxilla 6.0 mm advancement";
  s.model = "mtm";
  s.poisson_ratio = 0.46;
  s.tetrahedra = tetrahedra;
  s.nodes = 5;
  s.cell_size_mm = 7.5;
  s.meshing_attempts = 6;
  s.tet_budget = tet_budget;
  s.over_tet_budget = tetrahedra > tet_budget;
  s.soft_landmarks = {{"Sn", 4.04, 0.5, -0.3125, 4.1}};
  for (const char* kind : {"before", "after", "displacement"})
    for (const char* view : {"frontal", "lateral", "oblique"}) {
      const std::string name = std::string("soft-tissue-") + kind + "-" + view;
      stored.pictures[name] = "/objects/" + name;
    }
  return stored;
}

TEST(SoftTissueSection, AMeshOverItsBudgetIsReportedWithTheNumbers) {
  const std::string over = notes_of(soft_tissue_section(stored_prediction(2, 1)));
  EXPECT_NE(over.find("over its budget: 2 tetrahedra against at most 1 asked for, after 6 meshings up to a cell "
                      "size of 7.5 mm"),
            std::string::npos)
      << over;
  const std::string within = notes_of(soft_tissue_section(stored_prediction(2, 2)));
  EXPECT_EQ(within.find("budget"), std::string::npos) << within;
}

// The value of the model facts' row `key`, "" when there is none.
std::string fact(const report::Section& section, const std::string& key) {
  for (const auto* block : blocks_of<report::KeyValueBlock>(section))
    for (const auto& [k, v] : block->pairs)
      if (k == key) return v;
  return "";
}

TEST(SoftTissueSection, SaysWhichTissuesTheModelTellsApart) {
  auto stored = stored_prediction(2, 2);
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissues"), "one homogeneous soft tissue");
  stored.summary.nose_tets = 812;
  stored.summary.nose_stiffness = 30;
  stored.summary.nose_nodes_uncarried = 3;
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissues"),
            "soft tissue, and the cartilaginous nose (812 tetrahedra) 30 times stiffer, which follows the tissue, "
            "not the moved bone (3 of its nodes on the bone left free, as the septum is freed from the maxilla)");
  stored.summary.format_version = 5;  // before format 6 the moved bone carried the nose
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissues"),
            "soft tissue, and the cartilaginous nose (812 tetrahedra) 30 times stiffer");
}

TEST(SoftTissueSection, SaysHowTheTissueFollowsTheMovedBone) {
  auto stored = stored_prediction(2, 2);
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissue on moved bone"), "tied to it: moves with the bone");
  EXPECT_EQ(fact(soft_tissue_section(stored), "Nodes").find("sliding"), std::string::npos);
  stored.summary.bone_contact = "sliding";
  stored.summary.sliding_nodes = 321;
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissue on moved bone").rfind("slides on it", 0), 0u);
  EXPECT_NE(fact(soft_tissue_section(stored), "Nodes").find("321 sliding on it"), std::string::npos);
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissue on moved bone").find("pinched"), std::string::npos);
  stored.summary.squeezed_nodes_freed = 74;
  EXPECT_NE(fact(soft_tissue_section(stored), "Tissue on moved bone")
                .find("; 74 nodes pinched between moved and unmoved bone are left free"),
            std::string::npos);
}

TEST(SoftTissueSection, SaysWhenTissueShutInByBoneWasLeftOut) {
  auto stored = stored_prediction(2, 2);
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissues").find("shut in"), std::string::npos);
  stored.summary.enclosed_voxels_left_out = 64163;
  EXPECT_EQ(fact(soft_tissue_section(stored), "Tissues"),
            "one homogeneous soft tissue; the soft tissue shut in by bone within the region (the brain's base) is "
            "left out");
}

TEST(SoftTissueSection, AModelThatDidNotRunIsNamedWithWhy) {
  auto stored = stored_prediction(2, 2);
  EXPECT_EQ(notes_of(soft_tissue_section(stored)).find("was asked for"), std::string::npos);
  stored.summary.model = "fem";
  stored.summary.model_fallback = records::SimulationSummary::ModelFallback{"nfem", "Newton's method did not converge"};
  const std::string notes = notes_of(soft_tissue_section(stored));
  EXPECT_NE(notes.find("The non-linear FEM (neo-Hookean) was asked for and did not converge on this face (Newton's "
                       "method did not converge); the prediction shown is the linear FEM's"),
            std::string::npos)
      << notes;
}

TEST(SoftTissueSection, ShowsTheStoredPicturesAndLandmarkMoves) {
  const report::Section section = soft_tissue_section(stored_prediction(2, 2));
  const auto grids = blocks_of<report::ImageGrid>(section);
  ASSERT_EQ(grids.size(), 3u);  // before, after, displacement; no uncertainty band
  EXPECT_EQ(grids[1]->figures[1].caption, "Predicted, right lateral");
  EXPECT_EQ(grids[1]->figures[1].png, "/objects/soft-tissue-after-lateral");
  const auto tables = blocks_of<report::Table>(section);
  ASSERT_EQ(tables.size(), 1u);
  ASSERT_EQ(tables[0]->rows.size(), 1u);
  EXPECT_EQ(tables[0]->rows[0], (std::vector<std::string>{"Sn", "4.0", "0.5", "-0.3", "4.1"}));
}

TEST(SoftTissueSection, TheUncertaintyBandComesWithItsPictures) {
  records::StoredSimulation stored = stored_prediction(2, 2);
  stored.summary.uncertainty = records::SimulationSummary::UncertaintyBand{{"fem nu=0.46", "mtm nu=0.46"}, 0.25, 0.5};
  EXPECT_EQ(testing::error_of([&] { soft_tissue_section(stored); }),
            "artefact 9 (simulation): its picture soft-tissue-uncertainty-frontal is not stored");
  stored.pictures["soft-tissue-uncertainty-frontal"] = "/objects/u-f";
  stored.pictures["soft-tissue-uncertainty-lateral"] = "/objects/u-l";
  const report::Section section = soft_tissue_section(stored);
  EXPECT_EQ(blocks_of<report::ImageGrid>(section).size(), 4u);
  EXPECT_NE(notes_of(section).find("across 2 runs"), std::string::npos) << notes_of(section);
}

records::SimulationSummary::ProfileResponse profile_response(double nose_tip_ratio, bool mandible_moved) {
  records::SimulationSummary::ProfileResponse response;
  response.advancement_mm = 6;
  response.reference = "A";
  response.other_segments_moved = mandible_moved;
  response.points = {{"Prn", true, 6 * nose_tip_ratio, nose_tip_ratio, "0.17", "a 3D series", 0.0, 0.4},
                     {"Sn", true, 3.6, 0.6, "0.51 +/- 0.13", "Rosen 1988", 0.4, 0.95},
                     {"Li", true, 0.6, 0.1, "not measured", "", std::nullopt, std::nullopt},
                     {"PogS", false, 0, 0, "about 0", "", std::nullopt, std::nullopt}};
  response.gradient_p999 = 0.45;
  response.gradient_max = 2.5;
  response.steepest_near = "Li";
  response.steepest_near_mm = 3.25;
  return response;
}

TEST(SoftTissueSection, TheProfileIsJudgedAgainstThePublishedBands) {
  records::StoredSimulation stored = stored_prediction(2, 2);
  stored.summary.profile_response = profile_response(0.25, false);
  report::Section section = soft_tissue_section(stored);
  auto tables = blocks_of<report::Table>(section);
  ASSERT_EQ(tables.size(), 2u);  // the landmarks' moves, then the profile
  const auto& rows = tables[1]->rows;
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{"nose tip, pronasale (Prn)", "1.5", "0.25", "0.17", "0.00-0.40", "plausible"}));
  EXPECT_EQ(rows[2].back(), "no band");
  EXPECT_EQ(rows[3][1], "-");
  EXPECT_EQ(rows[3].back(), "not on the skin");
  EXPECT_NE(testing::paragraphs_of(section).find("Every point with a published band lies inside it"),
            std::string::npos);
  const std::string notes = notes_of(section);
  EXPECT_NE(notes.find("Sources: a 3D series; Rosen 1988."), std::string::npos) << notes;
  EXPECT_NE(notes.find("0.45 mm per mm (99.9th percentile of its edges), 2.5 at most, 3 mm from Li."),
            std::string::npos)
      << notes;
  EXPECT_EQ(notes.find("mandible"), std::string::npos) << notes;

  // A nose that rides on the maxilla is called out, and a moved mandible is named.
  stored.summary.profile_response = profile_response(0.9, true);
  section = soft_tissue_section(stored);
  tables = blocks_of<report::Table>(section);
  EXPECT_EQ(tables[1]->rows[0].back(), "OUTSIDE");
  EXPECT_NE(testing::paragraphs_of(section).find("1 point lies outside the plausible band"), std::string::npos);
  EXPECT_NE(notes_of(section).find("The mandible or the chin moved as well"), std::string::npos);
}

// Where the model's region cuts tissue, and whether the move has died out there.
TEST(SoftTissueSection, TheModelsEdgesAreNamedWithTheMoveThere) {
  records::StoredSimulation stored = stored_prediction(2, 2);
  stored.summary.boundary_moves = {{"below the orbits", 0.04}, {"under the chin", 0.0}};
  std::string notes = notes_of(soft_tissue_section(stored));
  EXPECT_NE(notes.find("within 5 mm inside each: below the orbits 0.04 mm, under the chin 0.00 mm. The move has "
                       "died out at every edge"),
            std::string::npos)
      << notes;
  stored.summary.boundary_moves[0].largest_move_mm = 1.38;
  notes = notes_of(soft_tissue_section(stored));
  EXPECT_NE(notes.find("The tissue still moves at the edge below the orbits: the prediction holds the face beyond"),
            std::string::npos)
      << notes;
  stored.summary.boundary_moves[1].largest_move_mm = 0.5;
  stored.summary.boundary_moves.push_back({"in front of the ears", 0.25});
  notes = notes_of(soft_tissue_section(stored));
  EXPECT_NE(notes.find("at the edges below the orbits, under the chin and in front of the ears: the prediction holds "
                       "the face beyond them"),
            std::string::npos)
      << notes;
  EXPECT_EQ(notes_of(soft_tissue_section(stored_prediction(2, 2))).find("edges"), std::string::npos);
}

TEST(SoftTissueSection, NoProfileTableWithoutAnAdvancedMaxilla) {
  const report::Section section = soft_tissue_section(stored_prediction(2, 2));
  EXPECT_EQ(blocks_of<report::Table>(section).size(), 1u);
  EXPECT_EQ(testing::paragraphs_of(section).find("Plausibility"), std::string::npos);
}

}  // namespace
}  // namespace maxillo::sections
