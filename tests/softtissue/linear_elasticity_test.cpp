#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "softtissue/cube_mesh.h"
#include "softtissue/linear_elasticity.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {
namespace {

Eigen::Matrix<double, 4, 3> skewed_tet() {
  Eigen::Matrix<double, 4, 3> p;
  p << 0.3, -0.2, 0.1, 4.1, 0.4, -0.3, 0.9, 3.2, 0.5, 0.2, 0.8, 2.7;
  return p;
}

// The 6 rigid modes of 4 points: 3 translations and 3 infinitesimal rotations w x p.
Eigen::Matrix<double, 12, 6> rigid_modes(const Eigen::Matrix<double, 4, 3>& p) {
  Eigen::Matrix<double, 12, 6> modes = Eigen::Matrix<double, 12, 6>::Zero();
  for (int a = 0; a < 4; ++a) {
    Eigen::Vector3d x = p.row(a).transpose();
    modes.block<3, 3>(3 * a, 0).setIdentity();
    for (int r = 0; r < 3; ++r) modes.block<3, 1>(3 * a, 3 + r) = Eigen::Vector3d::Unit(r).cross(x);
  }
  return modes;
}

TEST(ElementStiffness, RigidModesAreItsNullSpace) {
  Material material;
  Eigen::Matrix<double, 12, 12> k = element_stiffness(skewed_tet(), material);
  EXPECT_LT((k - k.transpose()).norm(), 1e-15 * k.norm());
  EXPECT_LT((k * rigid_modes(skewed_tet())).norm(), 1e-13 * k.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eigen(k);
  const auto& values = eigen.eigenvalues();  // ascending
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(values(i)), 1e-13 * values(11));
  EXPECT_GT(values(6), 1e-6 * values(11));  // exactly 6 zero modes: the others deform
}

TEST(ElementStiffness, UniformStrainEnergyMatchesHookesLaw) {
  // u = e x with symmetric strain e: energy = V/2 (lambda tr(e)^2 + 2 mu e:e).
  Material material{2.0, 0.3};
  LameParameters lame = lame_parameters(material);
  Eigen::Matrix3d e;
  e << 0.01, 0.002, -0.003, 0.002, -0.02, 0.004, -0.003, 0.004, 0.015;
  Eigen::Matrix<double, 4, 3> p = skewed_tet();
  Eigen::Matrix<double, 12, 1> u;
  for (int a = 0; a < 4; ++a) u.segment<3>(3 * a) = e * p.row(a).transpose();
  Eigen::Matrix3d edges;
  for (int a = 0; a < 3; ++a) edges.col(a) = (p.row(a + 1) - p.row(0)).transpose();
  double volume = edges.determinant() / 6;
  double expected = 0.5 * volume * (lame.lambda * e.trace() * e.trace() + 2 * lame.mu * (e.array() * e.array()).sum());
  EXPECT_NEAR(0.5 * u.dot(element_stiffness(p, material) * u), expected, 1e-12 * expected);
}

TEST(ElementStiffness, LameParametersFollowEquations6And7) {
  LameParameters lame = lame_parameters({1.0, 0.25});
  EXPECT_NEAR(lame.lambda, 0.4, 1e-15);
  EXPECT_NEAR(lame.mu, 0.4, 1e-15);
}

TEST(StiffnessBlocks, AssemblyMatchesElementSumAndKillsRigidMotion) {
  TetMesh mesh = make_cube_mesh({20.0, 3, HexSplit::kFiveTets});
  Material material;
  StiffnessBlocks blocks = assemble_stiffness_blocks(mesh, material);
  Eigen::SparseMatrix<double> k = to_sparse_matrix(blocks);
  // Dense reference by summing element matrices.
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * mesh.node_count(), 3 * mesh.node_count());
  for (int t = 0; t < mesh.tet_count(); ++t) {
    Eigen::Matrix<double, 12, 12> ke = element_stiffness(tet_corners(mesh, t), material);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        dense.block<3, 3>(3 * mesh.tets(t, a), 3 * mesh.tets(t, b)) += ke.block<3, 3>(3 * a, 3 * b);
  }
  EXPECT_LT((Eigen::MatrixXd(k) - dense).norm(), 1e-14 * dense.norm());
  // Rigid motion of the whole mesh: zero force on every node.
  Eigen::MatrixX3d u(mesh.node_count(), 3);
  Eigen::Vector3d w(0.01, -0.02, 0.03), t(1, 2, 3);
  for (int i = 0; i < mesh.node_count(); ++i) u.row(i) = (t + w.cross(Eigen::Vector3d(mesh.nodes.row(i)))).transpose();
  EXPECT_LT(multiply(blocks, u).norm(), 1e-12 * k.norm() * u.norm());
}

}  // namespace
}  // namespace maxillo::softtissue
