#include "softtissue/linear_elasticity.h"

#include <Eigen/Dense>

#include <cassert>

namespace maxillo::softtissue {

LameParameters lame_parameters(const Material& material) {
  const double e = material.young_modulus_mpa, nu = material.poisson_ratio;
  assert(e > 0 && nu > -1 && nu < 0.5 && "lame_parameters: need E > 0 and -1 < nu < 0.5");
  return {nu * e / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))};
}

Material scaled(const Material& material, double stiffness) {
  return {material.young_modulus_mpa * stiffness, material.poisson_ratio};
}

Eigen::Matrix<double, 4, 3> shape_gradients(const Eigen::Matrix<double, 4, 3>& corners) {
  Eigen::Matrix3d edges;  // columns: x1 - x0, x2 - x0, x3 - x0
  for (int a = 0; a < 3; ++a) edges.col(a) = (corners.row(a + 1) - corners.row(0)).transpose();
  // N_a for a = 1..3 are the barycentric coordinates: their gradients are the rows of edges^-1.
  Eigen::Matrix3d inverse = edges.inverse();
  Eigen::Matrix<double, 4, 3> gradients;
  gradients.bottomRows<3>() = inverse;
  gradients.row(0) = -inverse.colwise().sum();
  return gradients;
}

Eigen::Matrix<double, 12, 12> element_stiffness(const Eigen::Matrix<double, 4, 3>& corners, const Material& material) {
  Eigen::Matrix3d edges;
  for (int a = 0; a < 3; ++a) edges.col(a) = (corners.row(a + 1) - corners.row(0)).transpose();
  const double volume = edges.determinant() / 6.0;
  assert(volume > 0 && "element_stiffness: tet is degenerate or negatively oriented");
  const LameParameters lame = lame_parameters(material);
  const Eigen::Matrix<double, 4, 3> g = shape_gradients(corners);
  Eigen::Matrix<double, 12, 12> k;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      Eigen::Vector3d ga = g.row(a).transpose(), gb = g.row(b).transpose();
      k.block<3, 3>(3 * a, 3 * b) = volume * (lame.lambda * ga * gb.transpose() + lame.mu * gb * ga.transpose() +
                                              lame.mu * ga.dot(gb) * Eigen::Matrix3d::Identity());
    }
  return k;
}

}  // namespace maxillo::softtissue
