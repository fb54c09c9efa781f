#include "softtissue/boundary_conditions.h"

#include <algorithm>

namespace maxillo::softtissue {

Eigen::Vector3d BoundaryConditions::imposed(int i) const {
  if (constraint[size_t(i)] == NodeConstraint::kPrescribed) return displacement.row(i).transpose();
  return Eigen::Vector3d::Zero();
}

BoundaryConditions all_free(int node_count) {
  BoundaryConditions bc;
  bc.constraint.assign(size_t(node_count), NodeConstraint::kFree);
  bc.displacement = Eigen::MatrixX3d::Zero(node_count, 3);
  return bc;
}

int count_nodes(const BoundaryConditions& bc, NodeConstraint constraint) {
  return int(std::count(bc.constraint.begin(), bc.constraint.end(), constraint));
}

Eigen::MatrixX3d initial_displacement(const BoundaryConditions& bc) {
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(bc.node_count(), 3);
  for (int i = 0; i < bc.node_count(); ++i)
    if (!bc.is_free(i)) u.row(i) = bc.imposed(i).transpose();
  return u;
}

}  // namespace maxillo::softtissue
