#include "softtissue/rigid_plan_basis.h"

#include <cassert>

namespace maxillo::softtissue {

RigidPlanBasis precompute_rigid_plan_basis(const FactorisedElasticity& factorised, const TetMesh& mesh,
                                           const std::vector<NodeConstraint>& constraint,
                                           const std::vector<int>& segment_of_node, int segment_count) {
  assert(int(segment_of_node.size()) == mesh.node_count() && int(constraint.size()) == mesh.node_count() &&
         "precompute_rigid_plan_basis: arrays and mesh differ in node count");
  RigidPlanBasis basis;
  basis.segment_count = segment_count;
  BoundaryConditions bc = all_free(mesh.node_count());
  bc.constraint = constraint;
  for (int s = 0; s < segment_count; ++s)
    for (int c = 0; c < 12; ++c) {
      bc.displacement.setZero();
      for (int i = 0; i < mesh.node_count(); ++i) {
        if (constraint[size_t(i)] != NodeConstraint::kPrescribed || segment_of_node[size_t(i)] != s) continue;
        if (c < 9)
          bc.displacement(i, c / 3) = mesh.nodes(i, c % 3);  // A(r, k) X_k lands on axis r
        else
          bc.displacement(i, c - 9) = 1.0;
      }
      basis.responses.push_back(solve_factorised(factorised, bc));
    }
  return basis;
}

Eigen::MatrixX3d solve_rigid_plan(const RigidPlanBasis& basis, const std::vector<Eigen::Isometry3d>& motion) {
  assert(int(motion.size()) == basis.segment_count && "solve_rigid_plan: one motion per segment");
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(basis.responses.front().rows(), 3);
  for (int s = 0; s < basis.segment_count; ++s) {
    Eigen::Matrix3d a = motion[size_t(s)].linear() - Eigen::Matrix3d::Identity();
    Eigen::Vector3d t = motion[size_t(s)].translation();
    for (int c = 0; c < 12; ++c) {
      double weight = c < 9 ? a(c / 3, c % 3) : t(c - 9);
      if (weight != 0.0) u.noalias() += weight * basis.responses[size_t(12 * s + c)];
    }
  }
  return u;
}

}  // namespace maxillo::softtissue
