#pragma once
// Tetrahedral mass-spring model (thesis ch. 6, sec. 2.2): a mass point per node and a linear
// spring per mesh edge, force k (L - L0) along the spring (eqs. 3-4), with Van Gelder's spring
// constants k_e = E * (sum of the volumes of the tets sharing edge e) / L0_e^2 (eq. 5); where
// the tets' stiffness differs (TetMesh::stiffness), the sum weighs each volume by its tet's factor.
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

// Spring flip-over: a constrained node that jumps further than the rest length of a spring to
// a free neighbour passes through that neighbour; the spring, compressed through zero length,
// then pushes the neighbour the wrong way and the network settles folded (a valid but wrong
// equilibrium: springs have no volume term). So the imposed moves are applied in load steps of
// at most half the shortest spring between a constrained and a free node (at most 32 steps),
// each starting from the previous rest position: a quasi-static path. Measured on the cube
// benchmark (centre lifted 6 mm, threshold 1e-3 mm): at 29,000 tets (5.9 mm edges) one jump
// left 96 inverted tets and a node 8.3 mm from linear FEM, 3 load steps leave none and 1.25 mm.
// On finer meshes the network also folds on a quasi-static path, whatever the step count
// (4, 7 or 16 steps alike): 150 / 204 / 564 inverted tets at 64,000 / 105,000 / 197,000 tets
// (worst 6.0 / 5.5 / 5.2 mm from FEM, mean 0.44 / 0.35 / 0.43 mm), none for a 1 mm or 3 mm lift
// at 105,000 (worst 0.17 / 0.61 mm). That is the model, not the solver: under a 6 mm shear
// across 3-4 mm elements, folding a tet lowers the spring energy, as nothing resists inversion.
int mass_spring_load_steps(const MassSpringModel& model, const BoundaryConditions& bc);

// Static rest position; options apply to each load step, result.load_steps says how many.
LocalIterationResult solve_mass_spring(const MassSpringModel& model, const BoundaryConditions& bc,
                                       const LocalIterationOptions& options);

// Net spring force on each node (n x 3, N) in the displaced configuration.
Eigen::MatrixX3d spring_forces(const MassSpringModel& model, const Eigen::MatrixX3d& displacement);

}  // namespace maxillo::softtissue
