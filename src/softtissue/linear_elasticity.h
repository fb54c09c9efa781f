#pragma once
// Linear elasticity on linear tetrahedra (thesis ch. 6, eqs. 2 and 6-8). Lengths in mm,
// moduli in MPa, so forces are in N. For homogeneous tissue with only displacements imposed
// the static answer does not depend on Young's modulus; Poisson's ratio is 0.46 by default.
#include <Eigen/Core>

namespace maxillo::softtissue {

struct Material {
  double young_modulus_mpa = 0.003;  // about 3 kPa, soft facial tissue; scales forces only
  double poisson_ratio = 0.46;       // must lie in (-1, 0.5)
};

struct LameParameters {
  double lambda = 0;  // MPa, eq. 6
  double mu = 0;      // MPa, eq. 7 (shear modulus)
};
LameParameters lame_parameters(const Material& material);
// The material with its Young's modulus multiplied by `stiffness` (a tet's TetMesh::stiffness_of).
Material scaled(const Material& material, double stiffness);

// Gradients of the 4 linear shape functions of a tet (rows, 1/mm), from its corners (rows, mm).
Eigen::Matrix<double, 4, 3> shape_gradients(const Eigen::Matrix<double, 4, 3>& corners);

// The 12 x 12 element stiffness (N/mm), dofs ordered (x0, y0, z0, x1, ...). Block (a, b) is the
// thesis' tensor K_ab^T (eq. 8): K_ab = V (lambda g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I).
// Its null space holds the 6 rigid motions. Corners must be positively oriented.
Eigen::Matrix<double, 12, 12> element_stiffness(const Eigen::Matrix<double, 4, 3>& corners, const Material& material);

}  // namespace maxillo::softtissue
