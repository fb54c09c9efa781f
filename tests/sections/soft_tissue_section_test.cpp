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

}  // namespace
}  // namespace maxillo::sections
