// Tissue that slides on bone (NodeConstraint::kSliding): the node's move along the bone's normal is
// imposed, the two directions across it are solved for. Checked against the answers elasticity
// gives in closed form:
//  - a block pressed between two frictionless plates, its two other sides held by frictionless
//    walls, is in uniaxial stress: u = (nu d x / L, nu d y / L, -d z / L) for a press d, a
//    linear field that linear tetrahedra reproduce exactly. Tied to the plates it could not
//    widen, so that answer tells sliding from tying;
//  - a bone moving along its own surface carries none of the tissue that slides on it.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include "core/error.h"

#include "softtissue/block_pcg.h"
#include "softtissue/free_system.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/mass_spring_model.h"
#include "softtissue/mass_tensor_model.h"
#include "softtissue/nonlinear_fem.h"
#include "softtissue/stiffness_blocks.h"
#include "test_problems.h"

namespace maxillo::softtissue {
namespace {

constexpr double kBlockSide = 10.0;  // mm
const Material kTissue{0.003, 0.3};

TEST(SlidingNode, MovesOnlyAcrossItsNormalAndBalancesTheForceThere) {
  BoundaryConditions bc = all_free(1);
  const Eigen::Vector3d normal = Eigen::Vector3d(1, 2, 2) / 3, move(0.5, -1, 2);
  make_sliding(bc, 0, normal, move);
  EXPECT_NEAR(bc.imposed(0).dot(normal), move.dot(normal), 1e-12);
  EXPECT_LT(bc.imposed(0).cross(normal).norm(), 1e-12);
  EXPECT_LT(std::abs(bc.free_part(0, Eigen::Vector3d(3, -1, 4)).dot(normal)), 1e-12);
  Eigen::Matrix3d a;
  a << 4, 1, 0.5, 1, 3, -0.2, 0.5, -0.2, 2;  // symmetric positive definite
  const Eigen::Matrix3d m = bc.restricted_inverse(0, a);
  EXPECT_LT((m * normal).norm(), 1e-12);
  EXPECT_LT((m * a * m - m).norm(), 1e-12);
  // u = M f leaves no force across the normal: (a u - f) lies along it.
  const Eigen::Vector3d f(1, -2, 0.7), u = m * f;
  EXPECT_LT((a * u - f).cross(normal).norm(), 1e-12);
  EXPECT_LT((bc.restricted_solve(0, a, f) - u).norm(), 1e-12);
  // A free node is the plain inverse, a constrained one moves not at all.
  bc.constraint[0] = NodeConstraint::kFree;
  EXPECT_LT((bc.restricted_inverse(0, a) - a.inverse()).norm(), 1e-12);
  bc.constraint[0] = NodeConstraint::kPrescribed;
  EXPECT_TRUE(bc.restricted_inverse(0, a).isZero());
}

// The cube on frictionless supports: the walls x = 0 and y = 0 and the floor z = 0 stay where they
// are along their normals, the lid z = L presses down by `press`. A node on an edge keeps one of
// its walls (the floor or lid first): the answer is unique and meets every wall all the same.
// With `tied`, floor and lid hold their nodes in every direction.
struct PressedBlock {
  TetMesh mesh;
  BoundaryConditions bc;
};

PressedBlock pressed_block(double press, bool tied = false) {
  PressedBlock block{make_cube_mesh({kBlockSide, 4, HexSplit::kSixTets}), {}};
  block.bc = all_free(block.mesh.node_count());
  for (int i = 0; i < block.mesh.node_count(); ++i) {
    const Eigen::Vector3d p = block.mesh.nodes.row(i).transpose();
    if (p.x() < 1e-9) make_sliding(block.bc, i, Eigen::Vector3d::UnitX(), Eigen::Vector3d::Zero());
    if (p.y() < 1e-9) make_sliding(block.bc, i, Eigen::Vector3d::UnitY(), Eigen::Vector3d::Zero());
    const bool floor = p.z()<1e-9, lid = p.z()> kBlockSide - 1e-9;
    if (!floor && !lid) continue;
    const Eigen::Vector3d move(0, 0, lid ? -press : 0);
    if (tied) {
      block.bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      block.bc.displacement.row(i) = move.transpose();
    } else {
      make_sliding(block.bc, i, Eigen::Vector3d::UnitZ(), move);
    }
  }
  return block;
}

double error_from_uniaxial_stress(const TetMesh& mesh, const Eigen::MatrixX3d& u, double press, double nu) {
  Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
  gradient.diagonal() << nu * press / kBlockSide, nu * press / kBlockSide, -press / kBlockSide;
  return (u - testing::affine_field(mesh, gradient, Eigen::Vector3d::Zero())).cwiseAbs().maxCoeff();
}

TEST(SlidingContact, TheLinearFemPressesABlockBetweenFrictionlessPlatesIntoUniaxialStress) {
  const double press = 0.5;
  const auto block = pressed_block(press);
  const auto stiffness = assemble_stiffness_blocks(block.mesh, kTissue);
  const auto solution = solve_linear_static(stiffness, block.bc, {Preconditioner::kBlockJacobi, 1e-13, 5000});
  ASSERT_EQ(solution.status, SolveStatus::kConverged);
  EXPECT_LT(error_from_uniaxial_stress(block.mesh, solution.displacement, press, kTissue.poisson_ratio), 1e-9);
  EXPECT_LT(max_free_force(stiffness, block.bc, solution.displacement), 1e-9);
  // Tied to the plates the block cannot widen there: the same press gives another answer.
  const auto tied = pressed_block(press, true);
  const auto held = solve_linear_static(stiffness, tied.bc, {Preconditioner::kBlockJacobi, 1e-13, 5000});
  EXPECT_GT(error_from_uniaxial_stress(block.mesh, held.displacement, press, kTissue.poisson_ratio), 0.05);
  // The assembled solvers do not take sliding nodes, and say so rather than tie them.
  EXPECT_THROW(solve_linear_static(stiffness, block.bc, {Preconditioner::kJacobi, 1e-13, 5000}), Error);
}

TEST(SlidingContact, TheMassTensorModelComesToTheSameRest) {
  const double press = 0.5;
  const auto block = pressed_block(press);
  LocalIterationOptions options;
  options.gradient_threshold_mm = 1e-11;
  const auto result =
      solve_mass_tensor(make_mass_tensor_model(assemble_stiffness_blocks(block.mesh, kTissue)), block.bc, options);
  ASSERT_EQ(result.status, IterationStatus::kConverged);
  EXPECT_LT(error_from_uniaxial_stress(block.mesh, result.displacement, press, kTissue.poisson_ratio), 1e-7);
}

TEST(SlidingContact, TheNonLinearFemAgreesAtSmallStrain) {
  const double press = 0.02;  // 0.2 % strain: the neo-Hookean answer is the linear one to its square
  const auto block = pressed_block(press);
  NewtonOptions options;
  options.relative_tolerance = 1e-10;
  const auto solution = solve_nonlinear_static(block.mesh, kTissue, block.bc, options);
  ASSERT_TRUE(solution.converged);
  EXPECT_LT(error_from_uniaxial_stress(block.mesh, solution.displacement, press, kTissue.poisson_ratio), 2e-4);
}

// Springs have no Poisson ratio, so there is no closed form; the plates must still hold the nodes
// along their normals exactly and let them move across.
TEST(SlidingContact, TheMassSpringModelKeepsItsNodesOnThePlates) {
  const double press = 0.5;
  const auto block = pressed_block(press);
  LocalIterationOptions options;
  options.gradient_threshold_mm = 1e-8;
  const auto result = solve_mass_spring(make_van_gelder_model(block.mesh, 0.003), block.bc, options);
  ASSERT_EQ(result.status, IterationStatus::kConverged);
  double widest = 0;
  for (int i = 0; i < block.mesh.node_count(); ++i) {
    if (block.bc.constraint[size_t(i)] != NodeConstraint::kSliding) continue;
    const Eigen::Vector3d n = block.bc.normal.row(i).transpose(), u = result.displacement.row(i).transpose();
    EXPECT_NEAR(u.dot(n), block.bc.imposed(i).dot(n), 1e-12) << i;
    if (block.mesh.nodes(i, 0) > kBlockSide - 1e-9) widest = std::max(widest, u.x());
  }
  EXPECT_GT(widest, 0.01);  // the pressed block widens on the plates
}

// A slab of tissue lying on bone that moves along its own surface, its top held: sliding, the
// tissue does not move at all; tied, it shears.
TEST(SlidingContact, BoneMovingAlongItsSurfaceCarriesNoSlidingTissue) {
  const auto mesh = make_cube_mesh({kBlockSide, 3, HexSplit::kSixTets});
  const auto stiffness = assemble_stiffness_blocks(mesh, kTissue);
  for (bool slide : {true, false}) {
    BoundaryConditions bc = all_free(mesh.node_count());
    for (int i = 0; i < mesh.node_count(); ++i) {
      if (mesh.nodes(i, 2) > kBlockSide - 1e-9) bc.constraint[size_t(i)] = NodeConstraint::kFixed;
      if (mesh.nodes(i, 2) > 1e-9) continue;
      const Eigen::Vector3d along(2, 1, 0);
      if (slide) {
        make_sliding(bc, i, -Eigen::Vector3d::UnitZ(), along);
      } else {
        bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
        bc.displacement.row(i) = along.transpose();
      }
    }
    const auto fem = solve_linear_static(stiffness, bc, {Preconditioner::kBlockJacobi, 1e-12, 5000});
    LocalIterationOptions options;
    options.gradient_threshold_mm = 1e-10;
    const auto mtm = solve_mass_tensor(make_mass_tensor_model(stiffness), bc, options);
    if (slide) {
      EXPECT_LT(fem.displacement.cwiseAbs().maxCoeff(), 1e-12);
      EXPECT_LT(mtm.displacement.cwiseAbs().maxCoeff(), 1e-12);
    } else {
      EXPECT_GT(fem.displacement.cwiseAbs().maxCoeff(), 1.0);
    }
  }
}

}  // namespace
}  // namespace maxillo::softtissue
