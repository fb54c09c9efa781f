#include "softtissue/factorised_elasticity.h"

#include <Eigen/SparseCholesky>
#ifdef MAXILLO_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <cassert>

namespace maxillo::softtissue {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Simplicial = Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>>;
#ifdef MAXILLO_HAVE_CHOLMOD
using Supernodal = Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>;
#endif

SparseMatrix coupling_matrix(const StiffnessBlocks& stiffness, const FreeNodeNumbering& numbering,
                             const std::vector<int>& constrained_index, int constrained_count) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int f = 0; f < numbering.free_count(); ++f) {
    int i = numbering.free_nodes[size_t(f)];
    for (int e = stiffness.graph.row_begin(i); e < stiffness.graph.row_end(i); ++e) {
      int c = constrained_index[size_t(stiffness.graph.neighbours[size_t(e)])];
      if (c < 0) continue;
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) entries.emplace_back(3 * f + r, 3 * c + s, stiffness.blocks[size_t(e)](r, s));
    }
  }
  SparseMatrix coupling(3 * numbering.free_count(), 3 * constrained_count);
  coupling.setFromTriplets(entries.begin(), entries.end());
  return coupling;
}

template <class Factor>
FactorisationStatus factorise(const SparseMatrix& k, FactorisedElasticity& out) {
  auto factor = std::make_shared<Factor>();
  factor->compute(k);
  if (factor->info() != Eigen::Success) return FactorisationStatus::kNotPositiveDefinite;
  out.factorisation = factor;
  return FactorisationStatus::kOk;
}

}  // namespace

bool cholmod_available() {
#ifdef MAXILLO_HAVE_CHOLMOD
  return true;
#else
  return false;
#endif
}

FactorisationStatus precompute_factorisation(const StiffnessBlocks& stiffness,
                                             const std::vector<NodeConstraint>& constraint, CholeskyBackend backend,
                                             FactorisedElasticity& out) {
  if (backend == CholeskyBackend::kCholmodSupernodal && !cholmod_available())
    return FactorisationStatus::kBackendUnavailable;
  out = FactorisedElasticity{};
  out.backend = backend;
  out.numbering = number_free_nodes(constraint);
  std::vector<int> constrained_index(constraint.size(), -1);
  for (size_t i = 0; i < constraint.size(); ++i)
    if (constraint[i] != NodeConstraint::kFree) {
      constrained_index[i] = int(out.constrained_nodes.size());
      out.constrained_nodes.push_back(int(i));
    }
  out.coupling = coupling_matrix(stiffness, out.numbering, constrained_index, int(out.constrained_nodes.size()));
  const SparseMatrix k = free_free_matrix(stiffness, out.numbering);
  FactorisationStatus status = FactorisationStatus::kBackendUnavailable;
  if (backend == CholeskyBackend::kEigenSimplicial) {
    status = factorise<Simplicial>(k, out);
    if (status == FactorisationStatus::kOk)
      out.factor_nonzeros =
          static_cast<const Simplicial*>(out.factorisation.get())->matrixL().nestedExpression().nonZeros();
  }
#ifdef MAXILLO_HAVE_CHOLMOD
  if (backend == CholeskyBackend::kCholmodSupernodal) {
    status = factorise<Supernodal>(k, out);
    // Eigen keeps CHOLMOD's factor to itself; its workspace records the entries of L.
    if (status == FactorisationStatus::kOk)
      out.factor_nonzeros =
          long(const_cast<Supernodal*>(static_cast<const Supernodal*>(out.factorisation.get()))->cholmod().lnz);
  }
#endif
  return status;
}

Eigen::MatrixX3d solve_factorised(const FactorisedElasticity& factorised, const BoundaryConditions& bc) {
  assert(factorised.factorisation && "solve_factorised: precompute_factorisation did not succeed");
  const int nc = int(factorised.constrained_nodes.size());
  Eigen::VectorXd imposed(3 * nc);
  for (int c = 0; c < nc; ++c) {
    int i = factorised.constrained_nodes[size_t(c)];
    assert(!bc.is_free(i) && "solve_factorised: constraint pattern differs from the factorised one");
    imposed.segment<3>(3 * c) = bc.imposed(i);
  }
  const Eigen::VectorXd load = -(factorised.coupling * imposed);
  Eigen::VectorXd free_u;
  if (factorised.backend == CholeskyBackend::kEigenSimplicial)
    free_u = static_cast<const Simplicial*>(factorised.factorisation.get())->solve(load);
#ifdef MAXILLO_HAVE_CHOLMOD
  if (factorised.backend == CholeskyBackend::kCholmodSupernodal)
    free_u = static_cast<const Supernodal*>(factorised.factorisation.get())->solve(load);
#endif
  return assemble_displacement(free_u, factorised.numbering, bc);
}

}  // namespace maxillo::softtissue
