#include "softtissue/boundary_conditions.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>

namespace maxillo::softtissue {
namespace {

// Two unit vectors across `normal`, as the columns of a 3 x 2 matrix.
Eigen::Matrix<double, 3, 2> across(const Eigen::Vector3d& normal) {
  Eigen::Matrix<double, 3, 2> t;
  t.col(0) = normal.unitOrthogonal();
  t.col(1) = normal.cross(t.col(0));
  return t;
}

}  // namespace

Eigen::Vector3d BoundaryConditions::imposed(int i) const {
  switch (constraint[size_t(i)]) {
    case NodeConstraint::kPrescribed: return displacement.row(i).transpose();
    case NodeConstraint::kSliding: {
      const Eigen::Vector3d n = normal.row(i).transpose();
      return n * n.dot(displacement.row(i).transpose());
    }
    default: return Eigen::Vector3d::Zero();
  }
}

Eigen::Vector3d BoundaryConditions::free_part(int i, const Eigen::Vector3d& v) const {
  switch (constraint[size_t(i)]) {
    case NodeConstraint::kFree: return v;
    case NodeConstraint::kSliding: {
      const Eigen::Vector3d n = normal.row(i).transpose();
      return v - n * n.dot(v);
    }
    default: return Eigen::Vector3d::Zero();
  }
}

Eigen::Matrix3d BoundaryConditions::restricted_inverse(int i, const Eigen::Matrix3d& k) const {
  switch (constraint[size_t(i)]) {
    case NodeConstraint::kFree: return k.inverse();
    case NodeConstraint::kSliding: {
      const auto t = across(normal.row(i).transpose());
      return t * (t.transpose() * k * t).inverse() * t.transpose();
    }
    default: return Eigen::Matrix3d::Zero();
  }
}

Eigen::Vector3d BoundaryConditions::restricted_solve(int i, const Eigen::Matrix3d& k, const Eigen::Vector3d& f) const {
  switch (constraint[size_t(i)]) {
    case NodeConstraint::kFree: return k.ldlt().solve(f);
    case NodeConstraint::kSliding: {
      const auto t = across(normal.row(i).transpose());
      const Eigen::Matrix2d tangential = t.transpose() * k * t;
      return t * tangential.ldlt().solve(t.transpose() * f);
    }
    default: return Eigen::Vector3d::Zero();
  }
}

BoundaryConditions all_free(int node_count) {
  BoundaryConditions bc;
  bc.constraint.assign(size_t(node_count), NodeConstraint::kFree);
  bc.displacement = Eigen::MatrixX3d::Zero(node_count, 3);
  bc.normal = Eigen::MatrixX3d::Zero(node_count, 3);
  return bc;
}

void make_sliding(BoundaryConditions& bc, int i, const Eigen::Vector3d& normal, const Eigen::Vector3d& move) {
  if (bc.normal.rows() != bc.node_count()) bc.normal = Eigen::MatrixX3d::Zero(bc.node_count(), 3);
  bc.constraint[size_t(i)] = NodeConstraint::kSliding;
  bc.normal.row(i) = normal.normalized().transpose();
  bc.displacement.row(i) = move.transpose();
}

int count_nodes(const BoundaryConditions& bc, NodeConstraint constraint) {
  return int(std::count(bc.constraint.begin(), bc.constraint.end(), constraint));
}

bool any_sliding(const BoundaryConditions& bc) { return count_nodes(bc, NodeConstraint::kSliding) > 0; }

Eigen::MatrixX3d initial_displacement(const BoundaryConditions& bc) {
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(bc.node_count(), 3);
  for (int i = 0; i < bc.node_count(); ++i)
    if (!bc.is_free(i)) u.row(i) = bc.imposed(i).transpose();
  return u;
}

}  // namespace maxillo::softtissue
