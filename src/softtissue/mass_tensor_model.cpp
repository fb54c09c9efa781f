#include "softtissue/mass_tensor_model.h"

#include <Eigen/Dense>

#include <cassert>

namespace maxillo::softtissue {

MassTensorModel make_mass_tensor_model(const StiffnessBlocks& stiffness) {
  MassTensorModel model;
  const int n = stiffness.node_count();
  model.offsets.assign(size_t(n) + 1, 0);
  model.inverse_diagonal.resize(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) {
    for (int e = stiffness.graph.row_begin(j); e < stiffness.graph.row_end(j); ++e) {
      int k = stiffness.graph.neighbours[size_t(e)];
      if (k == j) {
        model.inverse_diagonal[size_t(j)] = stiffness.blocks[size_t(e)].inverse();
      } else {
        model.neighbours.push_back(k);
        model.neighbour_tensors.push_back(stiffness.blocks[size_t(e)]);
      }
    }
    model.offsets[size_t(j) + 1] = int(model.neighbours.size());
  }
  return model;
}

LocalIterationResult solve_mass_tensor(const MassTensorModel& model, const BoundaryConditions& bc,
                                       const LocalIterationOptions& options, const Eigen::MatrixX3d* start) {
  const int n = model.node_count();
  assert(bc.node_count() == n && "solve_mass_tensor: conditions and model differ in node count");
  LocalIterationResult result;
  result.displacement = initial_displacement(bc);
  if (start != nullptr)
    for (int j = 0; j < n; ++j)
      if (bc.has_free_directions(j))
        result.displacement.row(j) += bc.free_part(j, start->row(j).transpose()).transpose();
  // Row-major copy: each point's position is 3 contiguous doubles.
  std::vector<Eigen::Vector3d> u(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) u[size_t(j)] = result.displacement.row(j).transpose();
  // A sliding point j moves only across its normal, u_j = c_j + T a with c_j its imposed move:
  // its force across the normal vanishes where u_j = (I - M K_jj) c_j - M sum, M the inverse of
  // K_jj restricted to those directions. A free point has c_j = 0 and M = K_jj^-1 (eq. 12).
  std::vector<Eigen::Matrix3d> compliance = model.inverse_diagonal;
  std::vector<Eigen::Vector3d> offset(static_cast<size_t>(n), Eigen::Vector3d::Zero());
  for (int j = 0; j < n; ++j) {
    if (bc.constraint[size_t(j)] != NodeConstraint::kSliding) continue;
    const Eigen::Matrix3d k = model.inverse_diagonal[size_t(j)].inverse();
    compliance[size_t(j)] = bc.restricted_inverse(j, k);
    offset[size_t(j)] = (Eigen::Matrix3d::Identity() - compliance[size_t(j)] * k) * bc.imposed(j);
  }
  // Eq. 12: point j takes the position where its own force vanishes given its neighbours'.
  auto update_point = [&](int j) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int e = model.offsets[size_t(j)]; e < model.offsets[size_t(j) + 1]; ++e)
      sum.noalias() += model.neighbour_tensors[size_t(e)] * u[size_t(model.neighbours[size_t(e)])];
    Eigen::Vector3d step = options.relaxation * (offset[size_t(j)] - compliance[size_t(j)] * sum - u[size_t(j)]);
    u[size_t(j)] += step;
    return step;
  };
  sweep_until_rest(model.offsets, model.neighbours, bc, options, update_point, result);
  for (int j = 0; j < n; ++j) result.displacement.row(j) = u[size_t(j)].transpose();
  return result;
}

}  // namespace maxillo::softtissue
