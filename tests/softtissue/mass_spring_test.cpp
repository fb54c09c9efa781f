#include <gtest/gtest.h>

#include "softtissue/cube_benchmark.h"
#include "softtissue/factorised_elasticity.h"
#include "softtissue/mass_spring_model.h"
#include "test_problems.h"

namespace maxillo::softtissue {
namespace {

TEST(MassSpringModel, VanGelderConstantsFollowEquation5) {
  // One tet: each spring's constant is E V / L0^2.
  TetMesh mesh;
  mesh.nodes.resize(4, 3);
  mesh.nodes << 0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0, 4;
  mesh.tets.resize(1, 4);
  mesh.tets << 0, 1, 2, 3;
  MassSpringModel model = make_van_gelder_model(mesh, 0.5);
  EXPECT_EQ(model.spring_count(), 6);
  const double volume = 2.0 * 3.0 * 4.0 / 6.0;
  for (size_t s = 0; s < model.other_end.size(); ++s)
    EXPECT_NEAR(model.stiffness[s], 0.5 * volume / (model.rest_length[s] * model.rest_length[s]), 1e-15);
  // An edge shared by several tets sums their volumes: interior edges of a cube mesh.
  TetMesh cube = make_cube_mesh({10.0, 2, HexSplit::kSixTets});
  MassSpringModel cube_model = make_van_gelder_model(cube, 1.0);
  double largest = *std::max_element(cube_model.stiffness.begin(), cube_model.stiffness.end());
  EXPECT_GT(largest, 1.0 * (125.0 / 6.0) / 25.0);  // more than one tet's share on a 5 mm edge
}

// The springs are non-linear: a rigid motion of every constrained node, finite rotation
// included, leaves all springs at rest length, so it is the exact answer.
TEST(MassSpringModel, RigidMotionIsReproducedExactly) {
  TetMesh mesh = make_cube_mesh({40.0, 4, HexSplit::kFiveTets});
  MassSpringModel model = make_van_gelder_model(mesh, 0.003);
  for (const Eigen::Matrix3d& a : {Eigen::Matrix3d::Zero().eval(), testing::rotation_minus_identity(30.0)}) {
    Eigen::Vector3d b(3.0, -2.0, 1.0);
    BoundaryConditions bc = testing::affine_on_border(mesh, 40.0, a, b);
    LocalIterationResult result = solve_mass_spring(model, bc, {1e-12, 1.0, 100000});
    ASSERT_EQ(result.status, IterationStatus::kConverged);
    EXPECT_LT((result.displacement - testing::affine_field(mesh, a, b)).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(MassSpringModel, AtItsSweepLimitItSaysItDidNotConverge) {
  CubeSpec spec{100.0, 8, HexSplit::kSixTets};
  TetMesh mesh = make_cube_mesh(spec);
  BoundaryConditions bc = cube_benchmark_conditions(mesh, spec, {6.0, 15.0});
  const LocalIterationResult result = solve_mass_spring(make_van_gelder_model(mesh, 0.003), bc, {1e-9, 1.0, 3});
  EXPECT_EQ(result.status, IterationStatus::kIterationLimit);
  EXPECT_EQ(result.iterations, 3);
  EXPECT_GT(result.last_max_move_mm, 1e-9);
}

// The static solve reaches equilibrium, and its answer is not the FEM one: springs have no
// Poisson effect (documented in mass_spring_model.h), so the test records that they differ.
TEST(MassSpringModel, ReachesEquilibriumAndDiffersFromFem) {
  CubeSpec spec{100.0, 8, HexSplit::kSixTets};
  TetMesh mesh = make_cube_mesh(spec);
  BoundaryConditions bc = cube_benchmark_conditions(mesh, spec, {6.0, 15.0});
  MassSpringModel model = make_van_gelder_model(mesh, 0.003);
  LocalIterationResult result = solve_mass_spring(model, bc, {1e-9, 1.5, 100000});
  ASSERT_EQ(result.status, IterationStatus::kConverged);
  Eigen::MatrixX3d forces = spring_forces(model, result.displacement);
  Eigen::MatrixX3d start_forces = spring_forces(model, initial_displacement(bc));
  double largest = 0, largest_start = 0;
  for (int i = 0; i < mesh.node_count(); ++i)
    if (bc.is_free(i)) {
      largest = std::max(largest, forces.row(i).norm());
      largest_start = std::max(largest_start, start_forces.row(i).norm());
    }
  EXPECT_LT(largest, 1e-7 * largest_start);
  FactorisedElasticity fem;
  ASSERT_EQ(precompute_factorisation(assemble_stiffness_blocks(mesh, Material{}), bc.constraint,
                                     CholeskyBackend::kEigenSimplicial, fem),
            FactorisationStatus::kOk);
  Precision difference = precision_against(result.displacement, solve_factorised(fem, bc), testing::free_mask(bc));
  EXPECT_GT(difference.worst_mm, 0.05);
  EXPECT_LT(difference.worst_mm, 3.0);  // same order as the 6 mm lift: a sibling model, not garbage
}

}  // namespace
}  // namespace maxillo::softtissue
