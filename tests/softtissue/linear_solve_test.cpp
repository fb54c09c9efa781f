#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "softtissue/cube_benchmark.h"
#include "softtissue/factorised_elasticity.h"
#include "softtissue/free_system.h"
#include "softtissue/block_pcg.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/rigid_plan_basis.h"
#include "test_problems.h"

namespace maxillo::softtissue {
namespace {

using testing::affine_field;
using testing::affine_on_border;

struct SolverCase {
  HexSplit split;
  Preconditioner preconditioner;
};

class PatchTest : public ::testing::TestWithParam<SolverCase> {};

// A uniform strain prescribed on the border is reproduced exactly inside (linear FEM holds
// every affine field exactly).
TEST_P(PatchTest, KrylovReproducesUniformStrain) {
  TetMesh mesh = make_cube_mesh({40.0, 5, GetParam().split});
  Eigen::Vector3d b(0.3, -0.2, 0.1);
  BoundaryConditions bc = affine_on_border(mesh, 40.0, testing::general_gradient(), b);
  StiffnessBlocks k = assemble_stiffness_blocks(mesh, Material{});
  StaticSolution solution = solve_linear_static(k, bc, {GetParam().preconditioner, 1e-14, 5000});
  ASSERT_EQ(solution.status, SolveStatus::kConverged);
  EXPECT_LT((solution.displacement - affine_field(mesh, testing::general_gradient(), b)).cwiseAbs().maxCoeff(), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Solvers, PatchTest,
                         ::testing::Values(SolverCase{HexSplit::kFiveTets, Preconditioner::kJacobi},
                                           SolverCase{HexSplit::kSixTets, Preconditioner::kJacobi},
                                           SolverCase{HexSplit::kSixTets, Preconditioner::kIncompleteCholesky},
                                           SolverCase{HexSplit::kFiveTets, Preconditioner::kBlockJacobi},
                                           SolverCase{HexSplit::kSixTets, Preconditioner::kBlockJacobi}));

TEST(FactorisedElasticity, PatchTestAndFiniteRigidMotionAreExact) {
  TetMesh mesh = make_cube_mesh({40.0, 5, HexSplit::kFiveTets});
  StiffnessBlocks k = assemble_stiffness_blocks(mesh, Material{});
  BoundaryConditions bc = affine_on_border(mesh, 40.0, testing::general_gradient(), Eigen::Vector3d(1, 2, 3));
  FactorisedElasticity factorised;
  ASSERT_EQ(precompute_factorisation(k, bc.constraint, CholeskyBackend::kEigenSimplicial, factorised),
            FactorisationStatus::kOk);
  Eigen::MatrixX3d u = solve_factorised(factorised, bc);
  EXPECT_LT((u - affine_field(mesh, testing::general_gradient(), Eigen::Vector3d(1, 2, 3))).cwiseAbs().maxCoeff(),
            1e-9);
  // A plan moving all constrained nodes by one rigid transform (25 degrees and a shift) moves
  // every node by it: the boundary data is affine, so the linear answer is that same field.
  Eigen::Matrix3d rigid = testing::rotation_minus_identity(25.0);
  BoundaryConditions moved = affine_on_border(mesh, 40.0, rigid, Eigen::Vector3d(-4, 5, 6));
  EXPECT_LT((solve_factorised(factorised, moved) - affine_field(mesh, rigid, Eigen::Vector3d(-4, 5, 6)))
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
}

TEST(FactorisedElasticity, ReSolveMatchesKrylovAfterAPlanChange) {
  CubeSpec spec{100.0, 8, HexSplit::kSixTets};
  TetMesh mesh = make_cube_mesh(spec);
  StiffnessBlocks k = assemble_stiffness_blocks(mesh, Material{});
  BoundaryConditions bc = cube_benchmark_conditions(mesh, spec, {6.0, 15.0});
  ASSERT_GT(count_nodes(bc, NodeConstraint::kPrescribed), 0);
  FactorisedElasticity factorised;
  ASSERT_EQ(precompute_factorisation(k, bc.constraint, CholeskyBackend::kEigenSimplicial, factorised),
            FactorisationStatus::kOk);
  for (double lift : {6.0, -2.5}) {
    for (int i = 0; i < bc.node_count(); ++i)
      if (bc.constraint[size_t(i)] == NodeConstraint::kPrescribed) bc.displacement.row(i) << 0.5, 0.0, lift;
    Eigen::MatrixX3d direct = solve_factorised(factorised, bc);
    StaticSolution krylov = solve_linear_static(k, bc, {Preconditioner::kJacobi, 1e-12, 10000});
    ASSERT_EQ(krylov.status, SolveStatus::kConverged);
    EXPECT_LT((direct - krylov.displacement).cwiseAbs().maxCoeff(), 1e-8);
    // Residual: no net force on free nodes, relative to the forces the load puts on them.
    double load = max_free_force(k, bc, initial_displacement(bc));
    EXPECT_LT(max_free_force(k, bc, direct), 1e-10 * load);
  }
  if (cholmod_available()) {
    FactorisedElasticity supernodal;
    ASSERT_EQ(precompute_factorisation(k, bc.constraint, CholeskyBackend::kCholmodSupernodal, supernodal),
              FactorisationStatus::kOk);
    EXPECT_LT((solve_factorised(supernodal, bc) - solve_factorised(factorised, bc)).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(FactorisedElasticity, UnconstrainedMeshIsNotPositiveDefinite) {
  TetMesh mesh = make_cube_mesh({10.0, 2, HexSplit::kSixTets});
  StiffnessBlocks k = assemble_stiffness_blocks(mesh, Material{});
  FactorisedElasticity factorised;
  // No constrained node: the rigid motions are free, K_ff is singular.
  EXPECT_NE(precompute_factorisation(k, all_free(mesh.node_count()).constraint, CholeskyBackend::kEigenSimplicial,
                                     factorised),
            FactorisationStatus::kOk);
}

// A right-hand side with NaN (forces of an inverted neo-Hookean tet) has no answer: the block
// conjugate gradient says so at once instead of iterating NaN to its limit.
TEST(BlockPcg, ANonFiniteRightHandSideReturnsAtOnceUnconverged) {
  const auto mesh = make_cube_mesh({10.0, 2, HexSplit::kSixTets});
  const auto stiffness = assemble_stiffness_blocks(mesh, {0.003, 0.45});
  BoundaryConditions bc = testing::affine_on_border(mesh, 10.0, Eigen::Matrix3d::Zero(), Eigen::Vector3d::Zero());
  Eigen::VectorXd b = Eigen::VectorXd::Ones(3 * mesh.node_count());
  b(0) = std::numeric_limits<double>::quiet_NaN();
  bc.constraint.assign(bc.constraint.size(), NodeConstraint::kFree);  // every entry of b is read
  const BlockPcgResult result = solve_free_block_pcg(stiffness, bc, b, 1e-8, 20000);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 0);
  EXPECT_TRUE(std::isnan(result.relative_residual));
  EXPECT_TRUE(result.x.isZero());
}

// Newton's use on an indefinite tangent (a tissue near buckling): a stiffness shifted down by half
// its smallest diagonal block's eigenvalue keeps every diagonal block positive (so block Jacobi
// still applies) but has directions of negative curvature, the smooth ones. The truncated
// conjugate gradient stops at the first and returns a direction b points along (b . x > 0: downhill
// for an energy whose gradient is -b); on the unshifted stiffness the flag changes nothing.
TEST(BlockPcg, StopsAtNegativeCurvatureWithADescentDirection) {
  const auto mesh = make_cube_mesh({10.0, 4, HexSplit::kSixTets});
  StiffnessBlocks stiffness = assemble_stiffness_blocks(mesh, {0.003, 0.45});
  BoundaryConditions bc = all_free(mesh.node_count());
  bc.constraint[0] = NodeConstraint::kFixed;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(3 * mesh.node_count(), -1, 2);
  const BlockPcgResult plain = solve_free_block_pcg(stiffness, bc, b, 1e-8, 20000);
  const BlockPcgResult flagged = solve_free_block_pcg(stiffness, bc, b, 1e-8, 20000, true);
  EXPECT_FALSE(flagged.negative_curvature);
  EXPECT_EQ(flagged.iterations, plain.iterations);
  EXPECT_LT((flagged.x - plain.x).norm(), 1e-12 * plain.x.norm());

  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Matrix3d& block = stiffness.blocks[size_t(stiffness.graph.find(i, i))];
    smallest = std::min(smallest, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(block).eigenvalues()(0));
  }
  for (int i = 0; i < mesh.node_count(); ++i)
    stiffness.blocks[size_t(stiffness.graph.find(i, i))] -= 0.5 * smallest * Eigen::Matrix3d::Identity();
  const BlockPcgResult truncated = solve_free_block_pcg(stiffness, bc, b, 1e-8, 20000, true);
  EXPECT_TRUE(truncated.negative_curvature);
  EXPECT_FALSE(truncated.converged);
  EXPECT_GT(b.dot(truncated.x), 0);
  EXPECT_TRUE(truncated.x.allFinite());
}

// Scaling the mesh and the imposed displacements by s scales the answer by s (the static
// answer has no length scale of its own), for s = 1e3 and 1e-3.
TEST(LinearStatic, ScaleInvariance) {
  CubeSpec spec{100.0, 6, HexSplit::kFiveTets};
  TetMesh mesh = make_cube_mesh(spec);
  BoundaryConditions bc = cube_benchmark_conditions(mesh, spec, {6.0, 20.0});
  FactorisedElasticity reference;
  ASSERT_EQ(precompute_factorisation(assemble_stiffness_blocks(mesh, Material{}), bc.constraint,
                                     CholeskyBackend::kEigenSimplicial, reference),
            FactorisationStatus::kOk);
  Eigen::MatrixX3d u = solve_factorised(reference, bc);
  for (double s : {1e3, 1e-3}) {
    TetMesh scaled = mesh;
    scaled.nodes *= s;
    BoundaryConditions scaled_bc = bc;
    scaled_bc.displacement *= s;
    StaticSolution solution = solve_linear_static(assemble_stiffness_blocks(scaled, Material{}), scaled_bc,
                                                  {Preconditioner::kJacobi, 1e-13, 5000});
    ASSERT_EQ(solution.status, SolveStatus::kConverged);
    EXPECT_LT((solution.displacement / s - u).cwiseAbs().maxCoeff(), 1e-9);
  }
}

// Under refinement the lifting force of the cube benchmark decreases monotonically (the
// conforming linear FEM is too stiff and converges from above) and the steps shrink.
TEST(LinearStatic, ConvergesUnderRefinement) {
  std::vector<double> force;
  for (int k : {5, 10, 20}) {
    CubeSpec spec{100.0, k, HexSplit::kSixTets};
    TetMesh mesh = make_cube_mesh(spec);
    BoundaryConditions bc = cube_benchmark_conditions(mesh, spec, {6.0, 10.0});
    StiffnessBlocks blocks = assemble_stiffness_blocks(mesh, Material{});
    // The block-Jacobi conjugate gradient: the simplicial Cholesky of the finest mesh took 8-20 s.
    StaticSolution solution = solve_linear_static(blocks, bc, {Preconditioner::kBlockJacobi, 1e-10, 20000});
    ASSERT_EQ(solution.status, SolveStatus::kConverged);
    Eigen::MatrixX3d f = multiply(blocks, solution.displacement);
    double lift_force = 0;
    for (int i = 0; i < mesh.node_count(); ++i)
      if (bc.constraint[size_t(i)] == NodeConstraint::kPrescribed) lift_force += f(i, 2);
    force.push_back(lift_force);
  }
  EXPECT_GT(force[0], force[1]);
  EXPECT_GT(force[1], force[2]);
  EXPECT_LT(force[1] - force[2], force[0] - force[1]);
}

}  // namespace
}  // namespace maxillo::softtissue

namespace maxillo::softtissue {
namespace {

// Two bone segments move rigidly; the basis answer equals a full re-solve of that plan.
TEST(RigidPlanBasis, WeightedResponsesEqualTheDirectSolve) {
  CubeSpec spec{100.0, 8, HexSplit::kSixTets};
  TetMesh mesh = make_cube_mesh(spec);
  BoundaryConditions bc = cube_benchmark_conditions(mesh, spec, {6.0, 20.0});
  std::vector<int> segment(size_t(mesh.node_count()), -1);
  for (int i = 0; i < mesh.node_count(); ++i) segment[size_t(i)] = mesh.nodes(i, 0) < 50.0 ? 0 : 1;
  FactorisedElasticity factorised;
  ASSERT_EQ(precompute_factorisation(assemble_stiffness_blocks(mesh, Material{}), bc.constraint,
                                     CholeskyBackend::kEigenSimplicial, factorised),
            FactorisationStatus::kOk);
  RigidPlanBasis basis = precompute_rigid_plan_basis(factorised, mesh, bc.constraint, segment, 2);
  std::vector<Eigen::Isometry3d> motion(2, Eigen::Isometry3d::Identity());
  motion[0]
      .rotate(Eigen::AngleAxisd(0.2, Eigen::Vector3d(0, 1, 1).normalized()))
      .pretranslate(Eigen::Vector3d(1, 2, 3));
  motion[1].pretranslate(Eigen::Vector3d(0, 0, 5));
  BoundaryConditions plan = bc;
  for (int i = 0; i < mesh.node_count(); ++i)
    if (bc.constraint[size_t(i)] == NodeConstraint::kPrescribed) {
      Eigen::Vector3d x = mesh.nodes.row(i).transpose();
      plan.displacement.row(i) = (motion[size_t(segment[size_t(i)])] * x - x).transpose();
    }
  EXPECT_LT((solve_rigid_plan(basis, motion) - solve_factorised(factorised, plan)).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace maxillo::softtissue
