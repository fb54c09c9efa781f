// Tissues of different stiffness in one model (TetMesh::stiffness): a column of two tissues, the
// upper one k times stiffer, fixed at its foot and pulled up at its head. With Poisson's ratio 0
// nothing couples the axes, so the column is two springs in series: the stress is the same in
// both, each strains in inverse proportion to its modulus, and the interface rises by
// k / (1 + k) of the pull (linear FEM, the mass tensor model). For the neo-Hookean law with
// lambda = 0 a uniaxial stretch s gives the stress mu (s - 1/s) and no lateral one, so the
// exact answer is the stretches whose stresses balance, found here by bisection.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "softtissue/linear_static_solve.h"
#include "softtissue/mass_spring_model.h"
#include "softtissue/mass_tensor_model.h"
#include "softtissue/nonlinear_fem.h"
#include "softtissue/stiffness_blocks.h"
#include "test_problems.h"

namespace maxillo::softtissue {
namespace {

constexpr double kSide = 10.0;  // mm
const Material kNoPoisson{0.003, 0.0};

struct Column {
  TetMesh mesh;
  BoundaryConditions bc;
};

// The cube meshed with 4 divisions (the interface z = side / 2 is a grid plane), its upper half
// `upper_stiffness` times stiffer, the foot fixed and the head lifted by `pull` mm.
Column two_tissue_column(double upper_stiffness, double pull) {
  Column column;
  column.mesh = make_cube_mesh({kSide, 4, HexSplit::kSixTets});
  for (int t = 0; t < column.mesh.tet_count(); ++t) {
    const double centroid_z = tet_corners(column.mesh, t).col(2).mean();
    column.mesh.stiffness.push_back(centroid_z > kSide / 2 ? upper_stiffness : 1.0);
  }
  column.bc = all_free(column.mesh.node_count());
  for (int i = 0; i < column.mesh.node_count(); ++i) {
    const double z = column.mesh.nodes(i, 2);
    if (z < 1e-9) column.bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    if (z > kSide - 1e-9) {
      column.bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      column.bc.displacement.row(i) = Eigen::RowVector3d(0, 0, pull);
    }
  }
  return column;
}

// The largest distance of the model's answer from the exact two-spring field: u_z rises
// linearly to `interface_rise` at z = side / 2, then linearly to the pull; u_x = u_y = 0.
double error_from_series(const TetMesh& mesh, const Eigen::MatrixX3d& u, double interface_rise, double pull) {
  double worst = 0;
  for (int i = 0; i < mesh.node_count(); ++i) {
    const double z = mesh.nodes(i, 2), half = kSide / 2;
    const double expected =
        z <= half ? interface_rise * z / half : interface_rise + (pull - interface_rise) * (z - half) / half;
    worst = std::max(worst, (u.row(i) - Eigen::RowVector3d(0, 0, expected)).norm());
  }
  return worst;
}

TEST(TissueStiffness, LinearFemSplitsThePullInInverseProportionToTheModuli) {
  for (double k : {1.0, 9.0, 30.0}) {
    const auto column = two_tissue_column(k, 1.0);
    const auto solution = solve_linear_static(assemble_stiffness_blocks(column.mesh, kNoPoisson), column.bc,
                                              {Preconditioner::kJacobi, 1e-13, 5000});
    ASSERT_EQ(solution.status, SolveStatus::kConverged);
    EXPECT_LT(error_from_series(column.mesh, solution.displacement, k / (1 + k), 1.0), 1e-9) << "k = " << k;
  }
}

TEST(TissueStiffness, TheMassTensorModelComesToTheSameRest) {
  const auto column = two_tissue_column(9.0, 1.0);
  LocalIterationOptions options;
  options.gradient_threshold_mm = 1e-9;
  const auto result =
      solve_mass_tensor(make_mass_tensor_model(assemble_stiffness_blocks(column.mesh, kNoPoisson)), column.bc, options);
  ASSERT_EQ(result.status, IterationStatus::kConverged);
  EXPECT_LT(error_from_series(column.mesh, result.displacement, 0.9, 1.0), 1e-6);
}

// The stretch s in [lo, hi] where f(s) = 0, f increasing.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = (lo + hi) / 2;
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

TEST(TissueStiffness, TheNonLinearFemBalancesTheNeoHookeanStresses) {
  const double k = 9.0, pull = 3.0;  // 30 % overall stretch: far from linear
  const auto column = two_tissue_column(k, pull);
  NewtonOptions options;
  options.relative_tolerance = 1e-10;
  const auto solution = solve_nonlinear_static(column.mesh, kNoPoisson, column.bc, options);
  ASSERT_TRUE(solution.converged);
  // Lower stretch s1, upper s2 with (s1 - 1 + s2 - 1) side / 2 = pull and s1 - 1/s1 = k (s2 - 1/s2).
  const auto upper_stretch = [&](double s1) { return 2 * pull / kSide + 2 - s1; };
  const double s1 = bisect([&](double s) { return (s - 1 / s) - k * (upper_stretch(s) - 1 / upper_stretch(s)); }, 1.0,
                           1.0 + 2 * pull / kSide);
  const double interface_rise = (s1 - 1) * kSide / 2;
  EXPECT_GT(interface_rise, 0.9 * pull * 1.01);  // the non-linear answer is not the linear one
  EXPECT_LT(error_from_series(column.mesh, solution.displacement, interface_rise, pull), 1e-6);
}

// Springs have no Poisson ratio: the column narrows as it is pulled, so the series answer is not
// exact. The stiffer tissue must still take less of the pull, in the order of the moduli.
TEST(TissueStiffness, TheMassSpringModelStretchesTheStifferTissueLess) {
  LocalIterationOptions options;
  options.gradient_threshold_mm = 1e-7;
  std::vector<double> rises;
  for (double k : {1.0, 9.0, 30.0}) {
    const auto column = two_tissue_column(k, 1.0);
    const auto result = solve_mass_spring(make_van_gelder_model(column.mesh, 0.003), column.bc, options);
    ASSERT_EQ(result.status, IterationStatus::kConverged);
    double sum = 0;
    int count = 0;
    for (int i = 0; i < column.mesh.node_count(); ++i)
      if (std::abs(column.mesh.nodes(i, 2) - kSide / 2) < 1e-9) sum += result.displacement(i, 2), ++count;
    rises.push_back(sum / count);
  }
  EXPECT_NEAR(rises[0], 0.5, 0.05);
  EXPECT_GT(rises[1], rises[0] + 0.25);
  EXPECT_GT(rises[2], rises[1]);
  EXPECT_LT(rises[2], 1.0);
}

// Only ratios of stiffness matter when every load is an imposed displacement.
TEST(TissueStiffness, MultiplyingEveryTissueAlikeChangesNothing) {
  auto column = two_tissue_column(9.0, 1.0);
  const auto once = solve_linear_static(assemble_stiffness_blocks(column.mesh, kNoPoisson), column.bc,
                                        {Preconditioner::kJacobi, 1e-13, 5000});
  for (double& factor : column.mesh.stiffness) factor *= 7.0;
  const auto scaled = solve_linear_static(assemble_stiffness_blocks(column.mesh, kNoPoisson), column.bc,
                                          {Preconditioner::kJacobi, 1e-13, 5000});
  EXPECT_LT((once.displacement - scaled.displacement).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace maxillo::softtissue
