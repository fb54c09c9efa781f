#include "softtissue/linear_static_solve.h"

#include <Eigen/IterativeLinearSolvers>

#include "softtissue/block_pcg.h"
#include "softtissue/free_system.h"

namespace maxillo::softtissue {
namespace {

template <class Solver>
StaticSolution run(Solver& solver, const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& load,
                   const KrylovOptions& options) {
  StaticSolution solution;
  solver.setTolerance(options.relative_tolerance);
  solver.setMaxIterations(options.max_iterations);
  solver.compute(k);
  if (solver.info() != Eigen::Success) {
    solution.status = SolveStatus::kFactorisationFailed;
    return solution;
  }
  Eigen::VectorXd u = solver.solve(load);
  solution.iterations = int(solver.iterations());
  solution.relative_residual = solver.error();
  solution.status = solver.info() == Eigen::Success ? SolveStatus::kConverged : SolveStatus::kNotConverged;
  solution.displacement.resize(u.size() / 3, 3);
  for (Eigen::Index f = 0; f < u.size() / 3; ++f) solution.displacement.row(f) = u.segment<3>(3 * f).transpose();
  return solution;
}

}  // namespace

StaticSolution solve_linear_static(const StiffnessBlocks& stiffness, const BoundaryConditions& bc,
                                   const KrylovOptions& options) {
  if (options.preconditioner == Preconditioner::kBlockJacobi) return solve_block_pcg(stiffness, bc, options);
  const FreeNodeNumbering numbering = number_free_nodes(bc.constraint);
  const Eigen::SparseMatrix<double> k = free_free_matrix(stiffness, numbering);
  const Eigen::VectorXd load = free_load(stiffness, numbering, bc);
  StaticSolution solution;
  if (options.preconditioner == Preconditioner::kJacobi) {
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
    solution = run(solver, k, load, options);
  } else {
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                             Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>
        solver;
    solution = run(solver, k, load, options);
  }
  // run() returns free-node rows; spread them over all nodes with the imposed values.
  Eigen::VectorXd free_u(3 * numbering.free_count());
  if (solution.displacement.rows() == numbering.free_count())
    for (int f = 0; f < numbering.free_count(); ++f)
      free_u.segment<3>(3 * f) = solution.displacement.row(f).transpose();
  else
    free_u.setZero();
  solution.displacement = assemble_displacement(free_u, numbering, bc);
  return solution;
}

}  // namespace maxillo::softtissue
