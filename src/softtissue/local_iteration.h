#pragma once
// Shared pieces of the point-wise static solvers (mass tensor and mass-spring models): the
// local dynamic stop criterion and the report of a run.
#include <Eigen/Core>

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
  int iterations = 0;             // sweeps over the active points
  long point_updates = 0;         // local solves performed (the work)
  double last_max_move_mm = 0;    // largest point move in the last sweep (G_max)
};

// Precision of a result against the fully converged answer (thesis Table 1), over free nodes.
struct Precision {
  double worst_mm = 0;  // the thesis' P_min: the largest distance to the converged position
  double mean_mm = 0;   // P_mean
};
Precision precision_against(const Eigen::MatrixX3d& displacement, const Eigen::MatrixX3d& converged,
                            const Eigen::VectorX<bool>& is_free);

}  // namespace maxillo::softtissue
