#pragma once
// Shared pieces of the point-wise static solvers (mass tensor and mass-spring models): the
// local dynamic stop criterion and the report of a run.
#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "softtissue/boundary_conditions.h"

namespace maxillo::softtissue {

struct LocalIterationOptions {
  // Local dynamic stop criterion (thesis ch. 6, sec. 2.3.3): a point whose own update moved it
  // less than this (mm per iteration, the displacement gradient G) goes to rest; it is evaluated
  // again only after a neighbour moved by more. 0 iterates to max_iterations or exact rest.
  double gradient_threshold_mm = 1e-3;
  // Over-relaxation of each point update: 1 is the plain local solve of eq. 12; values in
  // (1, 2) extrapolate the step (successive over-relaxation) and cut the iteration count.
  double relaxation = 1.0;
  int max_iterations = 100000;
};

enum class IterationStatus { kConverged, kIterationLimit };

struct LocalIterationResult {
  Eigen::MatrixX3d displacement;  // n x 3, mm
  IterationStatus status = IterationStatus::kIterationLimit;
  int iterations = 0;           // sweeps over the active points
  long point_updates = 0;       // local solves performed (the work)
  double last_max_move_mm = 0;  // largest point move in the last sweep (G_max)
  int load_steps = 1;           // imposed moves applied in this many steps (mass-spring)
};

// The local dynamic stop criterion, shared by the point-wise solvers. Sweeps over the active
// points in index order; update_point(i) moves free or sliding point i by its local solve and
// returns the step (mm). A point that moved more than options.gradient_threshold_mm stays active
// and wakes its free and sliding neighbours (CSR adjacency: neighbours of i are
// neighbours[offsets[i]..offsets[i+1])),
// every other point goes to rest. Fills result's iterations, point_updates, last_max_move_mm
// and status; the caller fills the displacement.
template <typename UpdatePoint>
void sweep_until_rest(const std::vector<int>& offsets, const std::vector<int>& neighbours, const BoundaryConditions& bc,
                      const LocalIterationOptions& options, UpdatePoint&& update_point, LocalIterationResult& result) {
  const int n = bc.node_count();
  std::vector<char> active(static_cast<size_t>(n)), next(static_cast<size_t>(n), 0);
  for (int i = 0; i < n; ++i) active[size_t(i)] = bc.has_free_directions(i) ? 1 : 0;
  bool any_active = true;
  while (any_active && result.iterations < options.max_iterations) {
    any_active = false;
    double max_move = 0;
    for (int i = 0; i < n; ++i) {
      if (!active[size_t(i)]) continue;
      const double move = update_point(i).norm();
      ++result.point_updates;
      max_move = std::max(max_move, move);
      if (move <= options.gradient_threshold_mm) continue;
      next[size_t(i)] = 1;
      for (int e = offsets[size_t(i)]; e < offsets[size_t(i) + 1]; ++e)
        if (bc.has_free_directions(neighbours[size_t(e)])) next[size_t(neighbours[size_t(e)])] = 1;
      any_active = true;
    }
    active.swap(next);
    std::fill(next.begin(), next.end(), 0);
    result.last_max_move_mm = max_move;
    ++result.iterations;
  }
  result.status = any_active ? IterationStatus::kIterationLimit : IterationStatus::kConverged;
}

// Precision of a result against the fully converged answer (thesis Table 1), over free nodes.
struct Precision {
  double worst_mm = 0;  // the thesis' P_min: the largest distance to the converged position
  double mean_mm = 0;   // P_mean
};
Precision precision_against(const Eigen::MatrixX3d& displacement, const Eigen::MatrixX3d& converged,
                            const Eigen::VectorX<bool>& is_free);

}  // namespace maxillo::softtissue
