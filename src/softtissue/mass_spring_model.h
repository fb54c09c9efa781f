#pragma once
// Tetrahedral mass-spring model (thesis ch. 6, sec. 2.2): a mass point per node and a linear
// spring per mesh edge, force k (L - L0) along the spring (eqs. 3-4), with Van Gelder's spring
// constants k_e = E * (sum of the volumes of the tets sharing edge e) / L0_e^2 (eq. 5).
// The static rest position is found point by point, as for the mass tensor model: each free
// point takes a local Newton step towards zero force given its neighbours' positions, with
// the same dynamic cut-out (only points whose neighbours moved are evaluated again).
// The springs are geometrically non-linear: any rigid motion of all constrained points is
// reproduced exactly, large rotations included. The model is no discretisation of
// elasticity: its answer differs from the FEM one and does not converge to it under
// refinement (it has no Poisson ratio; see Van Gelder 1998).
#include <vector>

#include "softtissue/boundary_conditions.h"
#include "softtissue/local_iteration.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct MassSpringModel {
  Eigen::MatrixX3d rest_positions;  // n x 3, mm
  std::vector<int> offsets;         // n + 1: springs of node i are [offsets[i], offsets[i+1])
  std::vector<int> other_end;       // the spring's other node
  std::vector<double> stiffness;    // k, N/mm
  std::vector<double> rest_length;  // L0, mm
  int node_count() const { return int(rest_positions.rows()); }
  int spring_count() const { return int(other_end.size()) / 2; }  // each spring is stored at both ends
};

MassSpringModel make_van_gelder_model(const TetMesh& mesh, double young_modulus_mpa);

LocalIterationResult solve_mass_spring(const MassSpringModel& model, const BoundaryConditions& bc,
                                       const LocalIterationOptions& options);

// Net spring force on each node (n x 3, N) in the displaced configuration.
Eigen::MatrixX3d spring_forces(const MassSpringModel& model, const Eigen::MatrixX3d& displacement);

}  // namespace maxillo::softtissue
