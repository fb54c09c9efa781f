#include "softtissue/nonlinear_fem.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <cmath>
#include <vector>

#include "softtissue/free_system.h"

namespace maxillo::softtissue {
namespace {

using Matrix43 = Eigen::Matrix<double, 4, 3>;

// Reference geometry of every tet, computed once: shape gradients and volume.
struct Reference {
  std::vector<Matrix43> gradients;
  std::vector<double> volumes;
};

Reference reference_of(const TetMesh& mesh) {
  Reference r;
  r.gradients.reserve(size_t(mesh.tet_count()));
  r.volumes.reserve(size_t(mesh.tet_count()));
  for (int t = 0; t < mesh.tet_count(); ++t) {
    r.gradients.push_back(shape_gradients(tet_corners(mesh, t)));
    r.volumes.push_back(signed_volume(mesh, t));
  }
  return r;
}

Eigen::Matrix3d deformation_gradient(const TetMesh& mesh, int t, const Matrix43& g, const Eigen::MatrixX3d& u) {
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  for (int a = 0; a < 4; ++a) f += u.row(mesh.tets(t, a)).transpose() * g.row(a);
  return f;
}

Eigen::Matrix3d svk_stress(const Eigen::Matrix3d& e, const LameParameters& lame) {  // second Piola-Kirchhoff
  return lame.lambda * e.trace() * Eigen::Matrix3d::Identity() + 2 * lame.mu * e;
}

Eigen::MatrixX3d forces(const TetMesh& mesh, const Reference& ref, const LameParameters& lame, const Eigen::MatrixX3d& u) {
  Eigen::MatrixX3d f = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  for (int t = 0; t < mesh.tet_count(); ++t) {
    const auto& g = ref.gradients[size_t(t)];
    const Eigen::Matrix3d F = deformation_gradient(mesh, t, g, u);
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    const Eigen::Matrix3d P = F * svk_stress(E, lame);
    for (int a = 0; a < 4; ++a) f.row(mesh.tets(t, a)) += ref.volumes[size_t(t)] * (P * g.row(a).transpose()).transpose();
  }
  return f;
}

// Tangent stiffness on the free dofs: d f_a / d u_b for free nodes a, b.
Eigen::SparseMatrix<double> tangent(const TetMesh& mesh, const Reference& ref, const LameParameters& lame,
                                    const Eigen::MatrixX3d& u, const FreeNodeNumbering& numbering) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(mesh.tet_count()) * 144);
  for (int t = 0; t < mesh.tet_count(); ++t) {
    const auto& g = ref.gradients[size_t(t)];
    const double v = ref.volumes[size_t(t)];
    const Eigen::Matrix3d F = deformation_gradient(mesh, t, g, u);
    const Eigen::Matrix3d S = svk_stress(0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity()), lame);
    for (int b = 0; b < 4; ++b) {
      const int fb = numbering.free_index[size_t(mesh.tets(t, b))];
      if (fb < 0) continue;
      for (int k = 0; k < 3; ++k) {
        // Directional derivative of P for a unit move of node b along axis k.
        Eigen::Matrix3d dF = Eigen::Matrix3d::Zero();
        dF.row(k) = g.row(b);
        const Eigen::Matrix3d dE = 0.5 * (F.transpose() * dF + dF.transpose() * F);
        const Eigen::Matrix3d dP = dF * S + F * svk_stress(dE, lame);
        for (int a = 0; a < 4; ++a) {
          const int fa = numbering.free_index[size_t(mesh.tets(t, a))];
          if (fa < 0) continue;
          const Eigen::Vector3d column = v * dP * g.row(a).transpose();
          for (int i = 0; i < 3; ++i) entries.emplace_back(3 * fa + i, 3 * fb + k, column[i]);
        }
      }
    }
  }
  const int n = 3 * numbering.free_count();
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

Eigen::VectorXd free_residual(const Eigen::MatrixX3d& f, const FreeNodeNumbering& numbering) {
  Eigen::VectorXd r(3 * numbering.free_count());
  for (int i = 0; i < numbering.free_count(); ++i) r.segment<3>(3 * i) = f.row(numbering.free_nodes[size_t(i)]).transpose();
  return r;
}

}  // namespace

Eigen::MatrixX3d internal_forces(const TetMesh& mesh, const Material& material, const Eigen::MatrixX3d& u) {
  return forces(mesh, reference_of(mesh), lame_parameters(material), u);
}

NonlinearSolution solve_nonlinear_static(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
                                         const NewtonOptions& options) {
  const Reference ref = reference_of(mesh);
  const LameParameters lame = lame_parameters(material);
  const FreeNodeNumbering numbering = number_free_nodes(bc.constraint);
  NonlinearSolution solution;
  solution.displacement = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  double reference_norm = 0;
  for (int step = 1; step <= options.load_steps; ++step) {
    // Predictor: the imposed increment moves the free nodes as the current tangent says,
    // K_ff du_f = -(r + K_fc du_c); jumping the constrained nodes alone would invert the tets
    // around them. K_fc du_c is the directional derivative of the forces (a finite difference).
    Eigen::MatrixX3d increment = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
    for (int i = 0; i < mesh.node_count(); ++i)
      if (!bc.is_free(i)) increment.row(i) = bc.imposed(i).transpose() / options.load_steps;
    const Eigen::MatrixX3d f0 = forces(mesh, ref, lame, solution.displacement);
    constexpr double kEpsilon = 1e-4;
    const Eigen::VectorXd coupling =
        (free_residual(forces(mesh, ref, lame, solution.displacement + kEpsilon * increment), numbering) -
         free_residual(f0, numbering)) / kEpsilon;
    const Eigen::VectorXd r0 = free_residual(f0, numbering);
    if (reference_norm == 0) reference_norm = std::max((r0 + coupling).norm(), 1e-300);
    {
      const Eigen::SparseMatrix<double> k = tangent(mesh, ref, lame, solution.displacement, numbering);
      Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
      cg.setTolerance(options.linear_tolerance);
      cg.compute(k);
      const Eigen::VectorXd du = cg.solve(-(r0 + coupling));
      solution.linear_iterations += int(cg.iterations());
      solution.displacement += increment;
      for (int i = 0; i < numbering.free_count(); ++i)
        solution.displacement.row(numbering.free_nodes[size_t(i)]) += du.segment<3>(3 * i).transpose();
    }
    Eigen::VectorXd r = free_residual(forces(mesh, ref, lame, solution.displacement), numbering);
    solution.converged = false;
    for (int it = 0; it < options.max_iterations_per_step; ++it) {
      solution.relative_residual = r.norm() / reference_norm;
      if (solution.relative_residual <= options.relative_tolerance) {
        solution.converged = true;
        break;
      }
      // The solver keeps a reference to the matrix: it must outlive solve().
      const Eigen::SparseMatrix<double> k = tangent(mesh, ref, lame, solution.displacement, numbering);
      Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
      cg.setTolerance(options.linear_tolerance);
      cg.compute(k);
      const Eigen::VectorXd du = cg.solve(-r);
      solution.linear_iterations += int(cg.iterations());
      ++solution.newton_iterations;
      // Backtracking: halve the step until the residual decreases (Newton may overshoot).
      double alpha = 1;
      Eigen::MatrixX3d trial;
      Eigen::VectorXd trial_r;
      for (int halving = 0; halving < 8; ++halving, alpha /= 2) {
        trial = solution.displacement;
        for (int i = 0; i < numbering.free_count(); ++i)
          trial.row(numbering.free_nodes[size_t(i)]) += alpha * du.segment<3>(3 * i).transpose();
        trial_r = free_residual(forces(mesh, ref, lame, trial), numbering);
        if (trial_r.norm() < r.norm()) break;
      }
      solution.displacement = trial;
      r = trial_r;
    }
    if (!solution.converged) {
      solution.relative_residual = r.norm() / reference_norm;
      solution.converged = solution.relative_residual <= options.relative_tolerance;
    }
  }
  return solution;
}

}  // namespace maxillo::softtissue
