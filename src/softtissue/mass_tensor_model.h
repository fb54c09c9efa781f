#pragma once
// Mass tensor model (thesis ch. 6, sec. 2.3; Cotin et al.): per node the tensor K_jj (stored
// inverted) and per neighbour the tensor K_jk, i.e. the 3 x 3 blocks of the linear FEM
// stiffness. The static rest position is found directly (extension 1, eq. 12): each free point
// in turn takes the position where its own force vanishes given its neighbours',
//   u_j <- -K_jj^-1 sum_k K_jk u_k,
// with the local dynamic stop criterion (extension 2). Points are updated in place in node
// order, so a sweep uses each neighbour's newest position (Gauss-Seidel order). Converged, the
// answer is the linear FEM one.
#include <vector>

#include "softtissue/boundary_conditions.h"
#include "softtissue/local_iteration.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {

struct MassTensorModel {
  std::vector<int> offsets;                        // n + 1: neighbours of j are [offsets[j], offsets[j+1])
  std::vector<int> neighbours;                     // excluding j itself
  std::vector<Eigen::Matrix3d> neighbour_tensors;  // K_jk, N/mm
  std::vector<Eigen::Matrix3d> inverse_diagonal;   // K_jj^-1, mm/N
  int node_count() const { return int(inverse_diagonal.size()); }
};

// Precomputation: splits the FEM blocks into K_jj^-1 and K_jk.
MassTensorModel make_mass_tensor_model(const StiffnessBlocks& stiffness);

// Static solve. `start`, when given (n x 3), is the initial guess for free nodes and the free
// directions of sliding ones (e.g. the answer before a plan change); constrained nodes always
// take their imposed values. A sliding node takes its local solve across its normal.
LocalIterationResult solve_mass_tensor(const MassTensorModel& model, const BoundaryConditions& bc,
                                       const LocalIterationOptions& options, const Eigen::MatrixX3d* start = nullptr);

}  // namespace maxillo::softtissue
