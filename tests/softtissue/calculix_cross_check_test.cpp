// The soft tissue FEM against an independent solver: CalculiX (ccx, Debian's calculix-ccx), given
// the same tetrahedra (its C3D4, the same linear element), the same material and the same
// prescribed displacements, on a cube with its border held and its centre lifted.
// - Small strain: ccx's linear static step against the linear FEM (solve_linear_static).
// - Large strain: ccx's geometrically non-linear step (NLGEOM), where its *ELASTIC material is
//   St Venant-Kirchhoff, against the non-linear FEM with HyperelasticLaw::kStVenantKirchhoff.
// Both solve the same discrete equations, so the answers agree to the solvers' tolerances
// (measured 2026-11-29: 9e-9 mm linear; 3e-7 mm non-linear at a 4 mm lift, where the linear FEM's
// answer lies 2.0 mm away).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "softtissue/calculix_deck.h"
#include "softtissue/cube_mesh.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/nonlinear_fem.h"
#include "softtissue/stiffness_blocks.h"
#include "support/run_command.h"
#include "support/temporary_folder.h"

namespace maxillo::softtissue {
namespace {

constexpr double kCubeSideMm = 20;  // mm

struct CubeProblem {
  TetMesh mesh;
  BoundaryConditions bc;
  int centre = -1;
};

// The cube's border fixed and its centre node lifted by `lift_mm` along z.
CubeProblem lifted_cube(double lift_mm) {
  CubeProblem problem{make_cube_mesh({kCubeSideMm, 6, HexSplit::kSixTets}), {}, -1};
  problem.bc = all_free(problem.mesh.node_count());
  for (int i = 0; i < problem.mesh.node_count(); ++i) {
    const Eigen::Vector3d p = problem.mesh.nodes.row(i).transpose();
    if ((p.array() < 1e-9).any() || (p.array() > kCubeSideMm - 1e-9).any())
      problem.bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    if ((p - Eigen::Vector3d::Constant(kCubeSideMm / 2)).norm() < 1e-9) {
      problem.centre = i;
      problem.bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      problem.bc.displacement.row(i) = Eigen::RowVector3d(0, 0, lift_mm);
    }
  }
  return problem;
}

// Runs ccx on the problem's deck in a scratch folder and reads the displacements it printed.
Eigen::MatrixX3d solve_with_calculix(const CubeProblem& problem, const Material& material, CalculixStep step) {
  maxillo::testing::TemporaryFolder folder("calculix");
  std::ofstream(folder / "cube.inp") << calculix_deck(problem.mesh, material, problem.bc, step);
  const auto run = maxillo::testing::run_command("cd " + maxillo::testing::quote(folder.path()) +
                                                 " && OMP_NUM_THREADS=1 ccx -i cube > ccx.log 2>&1; echo $?");
  std::ifstream dat(folder / "cube.dat");
  const Eigen::MatrixX3d u = read_calculix_displacements(dat, problem.mesh.node_count());
  if (!u.allFinite()) {
    std::ifstream log(folder / "ccx.log");
    ADD_FAILURE() << "ccx exit " << run.output << ": " << std::string(std::istreambuf_iterator<char>(log), {});
  }
  return u;
}

class CalculixCrossCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!maxillo::testing::tool_available("ccx")) FAIL() << "ccx not found: scripts/setup installs calculix-ccx";
  }
};

TEST_F(CalculixCrossCheck, TheLinearFemMatchesCalculixLinearStatic) {
  const CubeProblem problem = lifted_cube(0.5);
  const Material material;  // the face model's
  const auto ours = solve_linear_static(assemble_stiffness_blocks(problem.mesh, material), problem.bc,
                                        KrylovOptions{Preconditioner::kBlockJacobi, 1e-12, 100000});
  ASSERT_EQ(ours.status, SolveStatus::kConverged);
  const Eigen::MatrixX3d theirs = solve_with_calculix(problem, material, CalculixStep::kLinear);
  ASSERT_TRUE(theirs.allFinite());
  EXPECT_GT(theirs.col(2).maxCoeff(), 0.49);  // the centre lifted
  EXPECT_LT((ours.displacement - theirs).cwiseAbs().maxCoeff(), 1e-5);
}

TEST_F(CalculixCrossCheck, TheNonlinearFemMatchesCalculixWithGeometricNonlinearity) {
  const CubeProblem problem = lifted_cube(4.0);  // 4 mm in 20: the centre's tets strain by tens of per cent
  const Material material;                       // the face model's
  NewtonOptions options;
  options.law = HyperelasticLaw::kStVenantKirchhoff;
  options.relative_tolerance = 1e-10;
  options.linear_tolerance = 1e-10;
  const auto ours = solve_nonlinear_static(problem.mesh, material, problem.bc, options);
  ASSERT_TRUE(ours.converged);
  const Eigen::MatrixX3d theirs = solve_with_calculix(problem, material, CalculixStep::kGeometricallyNonlinear);
  ASSERT_TRUE(theirs.allFinite());
  const auto linear = solve_linear_static(assemble_stiffness_blocks(problem.mesh, material), problem.bc);
  const double nonlinearity = (linear.displacement - theirs).cwiseAbs().maxCoeff();
  EXPECT_GT(nonlinearity, 0.05);  // large enough that the linear answer is not the non-linear one
  EXPECT_LT((ours.displacement - theirs).cwiseAbs().maxCoeff(), 1e-5) << "linear FEM differs by " << nonlinearity;
}

// What the deck cannot say is refused rather than written wrong: sliding nodes (an equation per
// node in CalculiX), and a mesh held nowhere.
TEST(CalculixDeck, RefusesSlidingNodesAndAMeshHeldNowhere) {
  const CubeProblem problem = lifted_cube(0.5);
  BoundaryConditions sliding = problem.bc;
  make_sliding(sliding, problem.centre, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, 0.5));
  EXPECT_THROW(calculix_deck(problem.mesh, Material{}, sliding), Error);
  EXPECT_THROW(calculix_deck(problem.mesh, Material{}, all_free(problem.mesh.node_count())), Error);
  std::istringstream nothing("no numbers here\n");
  EXPECT_FALSE(read_calculix_displacements(nothing, 3).allFinite());
}

}  // namespace
}  // namespace maxillo::softtissue
