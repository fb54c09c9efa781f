// The table of soft tissue models (softtissue/soft_tissue_model.h): every model once, its name
// read back to it, and the lists the commands show built from the same table.
#include "softtissue/soft_tissue_model.h"

#include <gtest/gtest.h>

#include <set>

namespace maxillo::softtissue {
namespace {

TEST(SoftTissueModels, EveryModelHasOneEntryWhoseNameReadsBack) {
  std::set<SoftTissueModel> seen;
  for (const auto& m : soft_tissue_models()) {
    EXPECT_TRUE(seen.insert(m.model).second) << m.name;
    EXPECT_EQ(parse_model(m.name), m.model);
    EXPECT_EQ(model_name(m.model), m.name);
    EXPECT_EQ(&model_info(m.model), &m);
  }
  for (auto model : {SoftTissueModel::kMassTensor, SoftTissueModel::kLinearFem, SoftTissueModel::kMassSpring,
                     SoftTissueModel::kNonlinearFem})
    EXPECT_EQ(seen.count(model), 1u) << int(model);
  EXPECT_FALSE(parse_model("springs"));
}

TEST(SoftTissueModels, TheCommandsListsComeFromTheTable) {
  EXPECT_EQ(model_names(), (std::vector<std::string>{"mtm", "fem", "msm", "nfem"}));
  EXPECT_EQ(model_choices(),
            "mtm (mass tensor model), fem (linear FEM), msm (mass-spring model) or nfem (non-linear FEM "
            "(neo-Hookean))");
  // The band re-solves with the two models that agree on the face; not the springs nor Newton.
  EXPECT_TRUE(model_info(SoftTissueModel::kMassTensor).in_uncertainty_band);
  EXPECT_TRUE(model_info(SoftTissueModel::kLinearFem).in_uncertainty_band);
  EXPECT_FALSE(model_info(SoftTissueModel::kMassSpring).in_uncertainty_band);
  EXPECT_FALSE(model_info(SoftTissueModel::kNonlinearFem).in_uncertainty_band);
}

}  // namespace
}  // namespace maxillo::softtissue
