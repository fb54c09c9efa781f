// Non-linear FEM (neo-Hookean by default, St Venant-Kirchhoff where named): frame invariance (a
// large rigid rotation costs nothing), the patch test for a large homogeneous deformation, and
// agreement with linear FEM for small moves.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "softtissue/cube_mesh.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/nonlinear_fem.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {
namespace {

TetMesh small_cube() { return make_cube_mesh({20.0, 4, HexSplit::kSixTets}); }

bool on_border(const Eigen::Vector3d& p, double side) {
  return (p.array() < 1e-9).any() || (p.array() > side - 1e-9).any();
}

// Border nodes prescribed to x -> map(x), interior free.
template <class Map>
BoundaryConditions border_follows(const TetMesh& mesh, Map&& map) {
  BoundaryConditions bc = all_free(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    if (!on_border(p, 20.0)) continue;
    bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
    bc.displacement.row(i) = (map(p) - p).transpose();
  }
  return bc;
}

template <class Map>
double max_error(const TetMesh& mesh, const Eigen::MatrixX3d& u, Map&& map) {
  double worst = 0;
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    worst = std::max(worst, (p + u.row(i).transpose() - map(p)).norm());
  }
  return worst;
}

TEST(NonlinearFem, ALargeRigidRotationIsStressFreeAndReproduced) {
  const auto mesh = small_cube();
  const Eigen::Isometry3d move =
      Eigen::Translation3d(3, -2, 5) * Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 1, 0).normalized());
  auto map = [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(move * p); };
  Eigen::MatrixX3d rigid(mesh.node_count(), 3);
  for (int i = 0; i < mesh.node_count(); ++i)
    rigid.row(i) = (map(mesh.nodes.row(i).transpose()) - mesh.nodes.row(i).transpose()).transpose();
  EXPECT_LT(internal_forces(mesh, {}, rigid).cwiseAbs().maxCoeff(), 1e-12);
  // Only the bottom face is moved; the rest of the cube is free and must follow rigidly.
  BoundaryConditions bc = all_free(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    if (p.z() > 1e-9) continue;
    bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
    bc.displacement.row(i) = (map(p) - p).transpose();
  }
  NewtonOptions options;
  options.relative_tolerance = 1e-10;
  options.load_steps = 12;  // about 5 degrees per step: Newton's basin of attraction
  auto solution = solve_nonlinear_static(mesh, {}, bc, options);
  EXPECT_TRUE(solution.converged);
  EXPECT_LT(max_error(mesh, solution.displacement, map), 1e-6);
  // Linear FEM cannot do this: its strain of a 57 degree rotation is not zero, so the free part
  // of the cube deforms.
  auto linear = solve_linear_static(assemble_stiffness_blocks(mesh, {}), bc);
  EXPECT_GT(max_error(mesh, linear.displacement, map), 0.5);
}

TEST(NonlinearFem, PatchTestWithALargeHomogeneousDeformation) {
  const auto mesh = small_cube();
  Eigen::Matrix3d f;
  f << 1.25, 0.2, 0, 0, 0.9, 0.1, 0.05, 0, 1.1;  // 25 % stretch, shear, compression
  auto map = [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(f * p + Eigen::Vector3d(1, 2, 3)); };
  NewtonOptions options;
  options.relative_tolerance = 1e-10;
  auto solution = solve_nonlinear_static(mesh, {}, border_follows(mesh, map), options);
  EXPECT_TRUE(solution.converged);
  EXPECT_LT(max_error(mesh, solution.displacement, map), 1e-6);
}

TEST(NonlinearFem, SmallMovesAgreeWithLinearFem) {
  const auto mesh = make_cube_mesh({20.0, 6, HexSplit::kSixTets});
  BoundaryConditions bc = all_free(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    if (on_border(p, 20.0)) bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    if ((p - Eigen::Vector3d(10, 10, 10)).norm() < 1e-9) {
      bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      bc.displacement.row(i) = Eigen::RowVector3d(0, 0, 0.01);  // 10 micrometres
    }
  }
  NewtonOptions options;
  options.load_steps = 1;
  auto nonlinear = solve_nonlinear_static(mesh, {}, bc, options);
  auto linear = solve_linear_static(assemble_stiffness_blocks(mesh, {}), bc);
  ASSERT_TRUE(nonlinear.converged);
  // Geometric non-linearity is second order in the displacement: ~1e-3 relative at 0.01 mm / 3 mm elements.
  EXPECT_LT((nonlinear.displacement - linear.displacement).cwiseAbs().maxCoeff(), 1e-3 * 0.01);
}

// The closed-form tangent of each law: at rest it is the linear stiffness, and at a large
// deformation it is the derivative of the internal forces (central differences, second-order accurate).
class TangentOfEachLaw : public ::testing::TestWithParam<HyperelasticLaw> {};

TEST_P(TangentOfEachLaw, IsTheLinearStiffnessAtRestAndTheForceDerivativeAway) {
  const HyperelasticLaw law = GetParam();
  const auto mesh = make_cube_mesh({20.0, 2, HexSplit::kFiveTets});
  const StiffnessBlocks linear = assemble_stiffness_blocks(mesh, {});
  const StiffnessBlocks at_rest = tangent_stiffness(mesh, {}, Eigen::MatrixX3d::Zero(mesh.node_count(), 3), law);
  ASSERT_EQ(at_rest.blocks.size(), linear.blocks.size());
  for (size_t e = 0; e < linear.blocks.size(); ++e) EXPECT_LT((at_rest.blocks[e] - linear.blocks[e]).norm(), 1e-12);

  Eigen::MatrixX3d u(mesh.node_count(), 3), v(mesh.node_count(), 3);
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    u.row(i) << 0.1 * p.y() + 0.002 * p.x() * p.z(), -0.05 * p.z(),
        0.15 * p.x() - 0.003 * p.y() * p.y();                                   // ~25 % strain
    v.row(i) << std::sin(0.3 * p.x()), std::cos(0.2 * p.y()), 0.1 * p.z() - 1;  // any direction
  }
  const double h = 1e-5;
  const Eigen::MatrixX3d difference =
      (internal_forces(mesh, {}, u + h * v, law) - internal_forces(mesh, {}, u - h * v, law)) / (2 * h);
  const Eigen::MatrixX3d product = multiply(tangent_stiffness(mesh, {}, u, law), v);
  EXPECT_LT((product - difference).cwiseAbs().maxCoeff(), 1e-6 * product.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(NonlinearFem, TangentOfEachLaw,
                         ::testing::Values(HyperelasticLaw::kStVenantKirchhoff, HyperelasticLaw::kNeoHookean));

// A neo-Hookean tet cannot be crushed flat: its forces are refused (NaN) once it turns inside
// out, which is how the line search keeps Newton away from inverted elements.
TEST(NonlinearFem, NeoHookeanRefusesAnInvertedTet) {
  const auto mesh = make_cube_mesh({20.0, 1, HexSplit::kFiveTets});
  Eigen::MatrixX3d flip = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  for (int i = 0; i < mesh.node_count(); ++i) flip(i, 2) = -2 * mesh.nodes(i, 2);  // mirror z: every tet inverted
  EXPECT_FALSE(internal_forces(mesh, {}, flip, HyperelasticLaw::kNeoHookean).allFinite());
  EXPECT_TRUE(internal_forces(mesh, {}, flip, HyperelasticLaw::kStVenantKirchhoff).allFinite());
}

// A node pushed towards a fixed face squeezes the tets between them. Pushed to 1 % above the face
// the tissue follows and stays the right way out. Pushed through it (150 % of the way), no load
// step gets past the face, however short: the step is halved down to the smallest, and the solve
// stops where the node meets the face (2/3 of the move) and says how far it got.
BoundaryConditions pushed_towards_the_floor(const TetMesh& mesh, double fraction_of_height) {
  BoundaryConditions bc = all_free(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    if (p.z() < 1e-9) bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    if ((p - Eigen::Vector3d(10, 10, 5)).norm() < 1e-9) {
      bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      bc.displacement.row(i) = Eigen::RowVector3d(0, 0, -5 * fraction_of_height);
    }
  }
  return bc;
}

TEST(NonlinearFem, AMoveThroughAFixedFaceStopsWhereItMeetsIt) {
  const auto mesh = small_cube();  // 5 mm cells: the pushed node is one cell above the floor
  NewtonOptions options;
  options.load_steps = 1;
  const auto near = solve_nonlinear_static(mesh, {}, pushed_towards_the_floor(mesh, 0.99), options);
  ASSERT_TRUE(near.converged);
  EXPECT_DOUBLE_EQ(near.load_reached, 1.0);
  EXPECT_TRUE(internal_forces(mesh, {}, near.displacement).allFinite());  // no tet inside out

  const auto through = solve_nonlinear_static(mesh, {}, pushed_towards_the_floor(mesh, 1.5), options);
  EXPECT_FALSE(through.converged);
  EXPECT_LT(through.load_reached, 1 / 1.5);
  EXPECT_GT(through.load_reached, 1 / 1.5 - 2 * options.smallest_load_fraction);
  EXPECT_GE(through.rejected_steps, 12);                                     // 1 -> 1/4096 at least once
  EXPECT_GE(through.load_steps, 2);                                          // halved steps taken, and grown again
  EXPECT_TRUE(internal_forces(mesh, {}, through.displacement).allFinite());  // the last state in equilibrium
}

}  // namespace
}  // namespace maxillo::softtissue
