// The soft-tissue section says when the face's tet mesh is over its budget, with the numbers.
#include "sections/soft_tissue_section.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>

namespace maxillo::sections {
namespace {

// A prediction on a two-tet mesh, meshed with the given budget.
casework::SoftTissuePrediction prediction_with_budget(int tet_budget) {
  casework::SoftTissuePrediction prediction;
  prediction.mesh.nodes.resize(5, 3);
  prediction.mesh.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  prediction.mesh.tets.resize(2, 4);
  prediction.mesh.tets << 0, 1, 2, 3, 1, 2, 3, 4;
  prediction.bc = softtissue::all_free(5);
  prediction.meshing = {.cell_size_mm = 7.5, .attempts = 6, .tet_budget = tet_budget};
  return prediction;
}

std::string notes_of(const report::Section& section) {
  std::string text;
  for (const auto& block : section.blocks)
    if (const auto* note = std::get_if<report::Note>(&block)) text += note->text + "\n";
  return text;
}

TEST(SoftTissueSection, AMeshOverItsBudgetIsReportedWithTheNumbers) {
  const SoftTissueSummary summary{"maxilla 6.0 mm advancement", {}, {}};
  const std::string over = notes_of(soft_tissue_section(prediction_with_budget(1), {}, {}, summary));
  EXPECT_NE(over.find("over its budget: 2 tetrahedra against at most 1 asked for, after 6 meshings up to a cell "
                      "size of 7.5 mm"),
            std::string::npos)
      << over;
  const std::string within = notes_of(soft_tissue_section(prediction_with_budget(2), {}, {}, summary));
  EXPECT_EQ(within.find("budget"), std::string::npos) << within;
}

}  // namespace
}  // namespace maxillo::sections
