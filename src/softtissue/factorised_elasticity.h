#pragma once
// Factorise once, re-solve on every plan change (libigl's precompute/solve split). The
// constraint pattern (which nodes are free) fixes K_ff and the coupling K_fc; a plan change
// only changes the prescribed displacements, so a re-solve is one sparse product and two
// triangular solves with the cached Cholesky factor of K_ff.
#include <memory>

#include "softtissue/boundary_conditions.h"
#include "softtissue/free_system.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {

enum class CholeskyBackend {
  kEigenSimplicial,    // Eigen::SimplicialLLT with AMD ordering
  kCholmodSupernodal,  // SuiteSparse CHOLMOD, supernodal (BLAS-3), when built with it
};
enum class FactorisationStatus { kOk, kNotPositiveDefinite, kBackendUnavailable };

bool cholmod_available();

struct FactorisedElasticity {
  FreeNodeNumbering numbering;
  std::vector<int> constrained_nodes;         // node of each constrained number
  Eigen::SparseMatrix<double> coupling;       // K_fc: 3 nf x 3 nc
  std::shared_ptr<const void> factorisation;  // the backend's factor of K_ff (opaque)
  CholeskyBackend backend = CholeskyBackend::kEigenSimplicial;
  long factor_nonzeros = 0;  // entries of L
};

// Factorises K_ff for this constraint pattern. On kOk `out` is ready for solve_factorised.
FactorisationStatus precompute_factorisation(const StiffnessBlocks& stiffness,
                                             const std::vector<NodeConstraint>& constraint, CholeskyBackend backend,
                                             FactorisedElasticity& out);

// Displacement of every node (n x 3, mm) for new imposed values; bc.constraint must equal the
// pattern given to precompute_factorisation.
Eigen::MatrixX3d solve_factorised(const FactorisedElasticity& factorised, const BoundaryConditions& bc);

}  // namespace maxillo::softtissue
