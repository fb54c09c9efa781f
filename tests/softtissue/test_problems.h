#pragma once
// Small problems shared by the soft tissue tests.
#include <Eigen/Geometry>

#include "softtissue/boundary_conditions.h"
#include "softtissue/cube_mesh.h"

namespace maxillo::softtissue::testing {

// Prescribes u(x) = a x + b on every node of the cube's border; interior nodes are free.
inline BoundaryConditions affine_on_border(const TetMesh& mesh, double side, const Eigen::Matrix3d& a,
                                           const Eigen::Vector3d& b) {
  BoundaryConditions bc = all_free(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) {
    Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    if ((p.array() <= 1e-9 * side).any() || (p.array() >= side * (1 - 1e-9)).any()) {
      bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      bc.displacement.row(i) = (a * p + b).transpose();
    }
  }
  return bc;
}

inline Eigen::MatrixX3d affine_field(const TetMesh& mesh, const Eigen::Matrix3d& a, const Eigen::Vector3d& b) {
  Eigen::MatrixX3d u(mesh.node_count(), 3);
  for (int i = 0; i < mesh.node_count(); ++i) u.row(i) = (a * mesh.nodes.row(i).transpose() + b).transpose();
  return u;
}

// A general (non-symmetric) displacement gradient: stretch, shear and a small rotation.
inline Eigen::Matrix3d general_gradient() {
  Eigen::Matrix3d a;
  a << 0.02, -0.01, 0.005, 0.03, -0.015, 0.01, -0.004, 0.02, 0.01;
  return a;
}

// R - I for a finite rotation of `degrees` about a tilted axis: u = (R - I) x + t is rigid.
inline Eigen::Matrix3d rotation_minus_identity(double degrees) {
  Eigen::Matrix3d r =
      Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  return r - Eigen::Matrix3d::Identity();
}

inline Eigen::VectorX<bool> free_mask(const BoundaryConditions& bc) {
  Eigen::VectorX<bool> mask(bc.node_count());
  for (int i = 0; i < bc.node_count(); ++i) mask(i) = bc.is_free(i);
  return mask;
}

}  // namespace maxillo::softtissue::testing
