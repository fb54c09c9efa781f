#include "softtissue/mass_spring_model.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace maxillo::softtissue {
namespace {

// Force on point i from its springs, and the local stiffness (the point's own Hessian block,
// with the transverse term of compressed springs dropped so it stays positive definite).
void local_force(const MassSpringModel& model, const std::vector<Eigen::Vector3d>& x, int i, Eigen::Vector3d& force,
                 Eigen::Matrix3d& hessian) {
  force.setZero();
  hessian.setZero();
  for (int s = model.offsets[size_t(i)]; s < model.offsets[size_t(i) + 1]; ++s) {
    Eigen::Vector3d d = x[size_t(model.other_end[size_t(s)])] - x[size_t(i)];
    double length = d.norm();
    double k = model.stiffness[size_t(s)], rest = model.rest_length[size_t(s)];
    Eigen::Vector3d direction = d / length;
    force += k * (length - rest) * direction;
    Eigen::Matrix3d axial = direction * direction.transpose();
    hessian += k * axial + k * std::max(0.0, 1.0 - rest / length) * (Eigen::Matrix3d::Identity() - axial);
  }
}

constexpr double kMaxStepOverRestLength = 0.5;  // a load step moves a constrained node by at most half a spring
constexpr int kMaxLoadSteps = 32;

}  // namespace

MassSpringModel make_van_gelder_model(const TetMesh& mesh, double young_modulus_mpa) {
  assert(young_modulus_mpa > 0 && "make_van_gelder_model: Young's modulus must be positive");
  MassSpringModel model;
  model.rest_positions = mesh.nodes;
  const NodeGraph graph = build_node_graph(mesh);
  std::vector<double> volume_sum(graph.neighbours.size(), 0.0);
  for (int t = 0; t < mesh.tet_count(); ++t) {
    double volume = signed_volume(mesh, t) * mesh.stiffness_of(t);  // E_t V_t, in units of E
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a != b) volume_sum[size_t(graph.find(mesh.tets(t, a), mesh.tets(t, b)))] += volume;
  }
  model.offsets.assign(graph.offsets.size(), 0);
  for (int i = 0; i < mesh.node_count(); ++i) {
    for (int e = graph.row_begin(i); e < graph.row_end(i); ++e) {
      int j = graph.neighbours[size_t(e)];
      if (j == i) continue;
      double rest = (mesh.nodes.row(j) - mesh.nodes.row(i)).norm();
      model.other_end.push_back(j);
      model.rest_length.push_back(rest);
      model.stiffness.push_back(young_modulus_mpa * volume_sum[size_t(e)] / (rest * rest));
    }
    model.offsets[size_t(i) + 1] = int(model.other_end.size());
  }
  return model;
}

Eigen::MatrixX3d spring_forces(const MassSpringModel& model, const Eigen::MatrixX3d& displacement) {
  const int n = model.node_count();
  std::vector<Eigen::Vector3d> x(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) x[size_t(i)] = (model.rest_positions.row(i) + displacement.row(i)).transpose();
  Eigen::MatrixX3d forces(n, 3);
  Eigen::Vector3d force;
  Eigen::Matrix3d hessian;
  for (int i = 0; i < n; ++i) {
    local_force(model, x, i, force, hessian);
    forces.row(i) = force.transpose();
  }
  return forces;
}

int mass_spring_load_steps(const MassSpringModel& model, const BoundaryConditions& bc) {
  double worst = 0;  // largest imposed move over the rest length of a spring to a free node
  for (int i = 0; i < model.node_count(); ++i) {
    if (bc.is_free(i)) continue;
    const double move = bc.imposed(i).norm();
    for (int s = model.offsets[size_t(i)]; s < model.offsets[size_t(i) + 1]; ++s)
      if (bc.has_free_directions(model.other_end[size_t(s)]))
        worst = std::max(worst, move / model.rest_length[size_t(s)]);
  }
  return std::clamp(int(std::ceil(worst / kMaxStepOverRestLength)), 1, kMaxLoadSteps);
}

LocalIterationResult solve_mass_spring(const MassSpringModel& model, const BoundaryConditions& bc,
                                       const LocalIterationOptions& options) {
  const int n = model.node_count();
  assert(bc.node_count() == n && "solve_mass_spring: conditions and model differ in node count");
  LocalIterationResult result;
  std::vector<Eigen::Vector3d> x(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) x[size_t(i)] = model.rest_positions.row(i).transpose();
  Eigen::Vector3d force;
  Eigen::Matrix3d hessian;
  // A local Newton step of point i towards zero net spring force, its neighbours held.
  auto update_point = [&](int i) {
    local_force(model, x, i, force, hessian);
    Eigen::Vector3d step = options.relaxation * bc.restricted_solve(i, hessian, force);
    x[size_t(i)] += step;
    return step;
  };
  // The imposed moves in load steps (see mass_spring_model.h), each from the previous rest.
  result.load_steps = mass_spring_load_steps(model, bc);
  for (int step = 1; step <= result.load_steps; ++step) {
    const double fraction = double(step) / result.load_steps;
    // A sliding node keeps its move across the normal from the last step.
    for (int i = 0; i < n; ++i)
      if (!bc.is_free(i)) {
        const Eigen::Vector3d rest = model.rest_positions.row(i).transpose();
        x[size_t(i)] = rest + fraction * bc.imposed(i) + bc.free_part(i, x[size_t(i)] - rest);
      }
    LocalIterationResult step_result;
    sweep_until_rest(model.offsets, model.other_end, bc, options, update_point, step_result);
    result.iterations += step_result.iterations;
    result.point_updates += step_result.point_updates;
    result.last_max_move_mm = step_result.last_max_move_mm;
    result.status = step_result.status;
    if (result.status != IterationStatus::kConverged) break;
  }
  result.displacement.resize(n, 3);
  for (int i = 0; i < n; ++i) result.displacement.row(i) = x[size_t(i)].transpose() - model.rest_positions.row(i);
  return result;
}

}  // namespace maxillo::softtissue
