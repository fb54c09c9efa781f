// The table of soft tissue models (softtissue/soft_tissue_model.h): every model once, its name
// read back to it, and the lists the commands show built from the same table.
#include "softtissue/soft_tissue_model.h"

#include <gtest/gtest.h>

#include <set>

#include "softtissue/cube_benchmark.h"
#include "softtissue/cube_mesh.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/mass_tensor_model.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {
namespace {

TEST(SoftTissueModels, EveryModelHasOneEntryWhoseNameReadsBack) {
  std::set<SoftTissueModel> seen;
  for (const auto& m : soft_tissue_models()) {
    EXPECT_TRUE(seen.insert(m.model).second) << m.name;
    EXPECT_EQ(parse_model(m.name), m.model);
    EXPECT_EQ(model_name(m.model), m.name);
    EXPECT_EQ(&model_info(m.model), &m);
    EXPECT_NE(m.solve, nullptr) << m.name;
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
  // `bench face` times the three models that solve the linear problem.
  EXPECT_TRUE(model_info(SoftTissueModel::kMassTensor).in_face_benchmark);
  EXPECT_TRUE(model_info(SoftTissueModel::kLinearFem).in_face_benchmark);
  EXPECT_TRUE(model_info(SoftTissueModel::kMassSpring).in_face_benchmark);
  EXPECT_FALSE(model_info(SoftTissueModel::kNonlinearFem).in_face_benchmark);
}

// The table's solver is the model's own, called as the case workflow always called it: the same
// answer to the bit as the solver called directly.
TEST(SoftTissueModels, TheTableSolvesWithTheModelsOwnSolver) {
  const CubeSpec spec{100.0, 4, HexSplit::kSixTets};
  const TetMesh mesh = make_cube_mesh(spec);
  const BoundaryConditions bc = cube_benchmark_conditions(mesh, spec);
  const ModelSolveOptions options;
  const auto blocks = assemble_stiffness_blocks(mesh, options.material);
  const auto fem = solve_model(SoftTissueModel::kLinearFem, mesh, bc, options);
  const auto direct_fem = solve_linear_static(blocks, bc);
  EXPECT_EQ(fem.displacement, direct_fem.displacement);
  EXPECT_EQ(fem.iterations, direct_fem.iterations);
  LocalIterationOptions local;
  local.gradient_threshold_mm = options.gradient_threshold_mm;  // one tissue: no stiffness contrast
  local.max_iterations = options.max_sweeps;
  const auto mtm = solve_model(SoftTissueModel::kMassTensor, mesh, bc, options);
  const auto direct_mtm = solve_mass_tensor(make_mass_tensor_model(blocks), bc, local);
  EXPECT_EQ(mtm.displacement, direct_mtm.displacement);
  EXPECT_EQ(mtm.iterations, direct_mtm.iterations);
}

}  // namespace
}  // namespace maxillo::softtissue
