// What issue 3 asks of every soft tissue model where the other test files do not already check
// it: the patch test of the mass-spring model, and convergence under mesh refinement of the
// mass tensor, mass-spring and non-linear FEM models (linear FEM: linear_solve_test.cpp).
// Patch tests and rigid plans of the other models: linear_solve_test.cpp (fem),
// mass_tensor_test.cpp (mtm), mass_spring_test.cpp (msm rigid), nonlinear_fem_test.cpp (nfem).
//
// Refinement is measured on the cube benchmark with its 20 mm centre block lifted 6 mm, at 5,
// 10 and 20 divisions (the block's faces lie on grid planes at all three, so the problem is
// the same), through the force that holds the block up: a scalar of the continuum answer.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "softtissue/cube_benchmark.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/mass_spring_model.h"
#include "softtissue/mass_tensor_model.h"
#include "softtissue/nonlinear_fem.h"
#include "test_problems.h"

namespace maxillo::softtissue {
namespace {

constexpr int kRefinements[] = {5, 10, 20};

struct RefinedCube {
  CubeSpec spec;
  TetMesh mesh;
  BoundaryConditions bc;
};

RefinedCube refined_cube(int divisions) {
  RefinedCube cube{{100.0, divisions, HexSplit::kSixTets}, {}, {}};
  cube.mesh = make_cube_mesh(cube.spec);
  cube.bc = cube_benchmark_conditions(cube.mesh, cube.spec, {6.0, 10.0});
  return cube;
}

// Upward force (N) the prescribed nodes need, from nodal forces f (n x 3) in the sign of K u.
double lift_force(const BoundaryConditions& bc, const Eigen::MatrixX3d& f) {
  double sum = 0;
  for (int i = 0; i < bc.node_count(); ++i)
    if (bc.constraint[size_t(i)] == NodeConstraint::kPrescribed) sum += f(i, 2);
  return sum;
}

// The successive changes of a refined quantity shrink: |q1 - q2| < |q0 - q1|.
void expect_converging(const std::vector<double>& q, const char* model) {
  ASSERT_EQ(q.size(), 3u);
  EXPECT_LT(std::abs(q[1] - q[2]), std::abs(q[0] - q[1])) << model << ": " << q[0] << ", " << q[1] << ", " << q[2];
}

// The mass-spring patch test. On the structured cube meshes (six-tet Kuhn split and the
// alternating five-tet split) every interior node's springs come in opposite pairs, (i, i + d)
// and (i - d, i), with equal rest length and equal Van Gelder constant (congruent rings of
// tets). An affine map x -> F x + b stretches both alike and their forces cancel, so a uniform
// strain is an exact equilibrium, whatever F. Move the interior nodes off the grid and the
// pairs differ: the network no longer reproduces a uniform strain. That is the model, not the
// solver: its constants come from the tets' volumes, not from an energy of the strain (Van
// Gelder 1998), so on the irregular face mesh a uniform strain is only approximated. Both
// outcomes are checked so that a change of either is noticed.
TEST(MassSpringModel, PatchTestIsExactOnStructuredMeshesOnly) {
  const Eigen::Vector3d b(0.3, -0.2, 0.1);
  for (HexSplit split : {HexSplit::kSixTets, HexSplit::kFiveTets}) {
    for (bool irregular : {false, true}) {
      TetMesh mesh = make_cube_mesh({40.0, 5, split});
      if (irregular)  // a fixed pseudo-random shift of up to 1 mm (edges 8 mm) of every interior node
        for (int i = 0; i < mesh.node_count(); ++i) {
          const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
          if ((p.array() > 1e-9).all() && (p.array() < 40.0 - 1e-9).all())
            mesh.nodes.row(i) += Eigen::RowVector3d(std::sin(7.0 * i), std::cos(11.0 * i), std::sin(13.0 * i + 1));
        }
      MassSpringModel model = make_van_gelder_model(mesh, 0.003);
      BoundaryConditions bc = testing::affine_on_border(mesh, 40.0, testing::general_gradient(), b);
      LocalIterationResult result = solve_mass_spring(model, bc, {1e-12, 1.5, 100000});
      ASSERT_EQ(result.status, IterationStatus::kConverged);
      const double error =
          (result.displacement - testing::affine_field(mesh, testing::general_gradient(), b)).cwiseAbs().maxCoeff();
      if (irregular)
        EXPECT_GT(error, 1e-3) << "five-tet split " << (split == HexSplit::kFiveTets);  // strains of a few per cent
      else
        EXPECT_LT(error, 1e-9) << "five-tet split " << (split == HexSplit::kFiveTets);
    }
  }
}

// The converged mass tensor answer is the linear FEM one, so it refines as FEM does: the
// lifting force decreases (conforming FEM is too stiff) with shrinking steps.
TEST(MassTensorModel, ConvergesUnderRefinement) {
  std::vector<double> force;
  for (int divisions : kRefinements) {
    RefinedCube cube = refined_cube(divisions);
    StiffnessBlocks stiffness = assemble_stiffness_blocks(cube.mesh, Material{});
    LocalIterationResult result = solve_mass_tensor(make_mass_tensor_model(stiffness), cube.bc, {1e-7, 1.8, 200000});
    ASSERT_EQ(result.status, IterationStatus::kConverged);
    force.push_back(lift_force(cube.bc, multiply(stiffness, result.displacement)));
  }
  EXPECT_GT(force[0], force[1]);
  EXPECT_GT(force[1], force[2]);
  expect_converging(force, "mtm");
}

// Non-linear FEM (neo-Hookean): the lifting force converges under refinement, and its limit stays
// near the linear one (6 mm on a 100 mm cube is a moderate strain).
TEST(NonlinearFem, ConvergesUnderRefinement) {
  std::vector<double> force;
  for (int divisions : kRefinements) {
    RefinedCube cube = refined_cube(divisions);
    NewtonOptions options;
    options.load_steps = 1;
    NonlinearSolution solution = solve_nonlinear_static(cube.mesh, Material{}, cube.bc, options);
    ASSERT_TRUE(solution.converged);
    force.push_back(lift_force(cube.bc, internal_forces(cube.mesh, Material{}, solution.displacement)));
  }
  EXPECT_GT(force[0], force[1]);
  EXPECT_GT(force[1], force[2]);
  expect_converging(force, "nfem");
}

// The limit of a sequence from three terms by Aitken's extrapolation (geometric convergence).
double extrapolated_limit(const std::vector<double>& q) {
  return q[2] - (q[2] - q[1]) * (q[2] - q[1]) / ((q[2] - q[1]) - (q[1] - q[0]));
}

// Mass-spring: the network refines towards a limit of its own (successive changes shrink),
// which is not the continuum (FEM) answer: a Van Gelder network behaves as a material whose
// Poisson ratio is fixed by the lattice, not the 0.46 of Material{}, and Van Gelder (1998)
// shows no choice of constants makes springs equal to FEM. Measured lifting forces (N) at 5,
// 10, 20 divisions: springs 3.13, 2.44, 2.15 (limit ~1.94); linear FEM 7.09, 4.11, 3.14
// (limit ~2.67). The spring force is the springs' pull on the node, so the lift is -f.
TEST(MassSpringModel, ConvergesUnderRefinementToALimitOfItsOwn) {
  std::vector<double> force, fem_force;
  for (int divisions : kRefinements) {
    RefinedCube cube = refined_cube(divisions);
    MassSpringModel model = make_van_gelder_model(cube.mesh, Material{}.young_modulus_mpa);
    LocalIterationResult result = solve_mass_spring(model, cube.bc, {1e-7, 1.8, 200000});
    ASSERT_EQ(result.status, IterationStatus::kConverged);
    force.push_back(-lift_force(cube.bc, spring_forces(model, result.displacement)));
    const StiffnessBlocks stiffness = assemble_stiffness_blocks(cube.mesh, Material{});
    const StaticSolution fem = solve_linear_static(stiffness, cube.bc, {Preconditioner::kBlockJacobi, 1e-10, 20000});
    ASSERT_EQ(fem.status, SolveStatus::kConverged);
    fem_force.push_back(lift_force(cube.bc, multiply(stiffness, fem.displacement)));
  }
  expect_converging(force, "msm");
  expect_converging(fem_force, "fem");
  const double spring_limit = extrapolated_limit(force), fem_limit = extrapolated_limit(fem_force);
  EXPECT_GT(spring_limit, 0);
  EXPECT_LT(spring_limit, 0.85 * fem_limit) << "springs " << spring_limit << " N, FEM " << fem_limit << " N";
}

}  // namespace
}  // namespace maxillo::softtissue
