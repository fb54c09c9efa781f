#include "softtissue/nonlinear_fem.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/LU>

#include "softtissue/block_pcg.h"

namespace maxillo::softtissue {
namespace {

using Matrix43 = Eigen::Matrix<double, 4, 3>;

// Reference geometry of every tet, computed once: shape gradients, weights, and where each of
// the tet's 16 node-pair blocks lives in the node graph (so assembling the tangent at every
// Newton step needs no graph search). Both Lame parameters are proportional to Young's
// modulus, so a tet's stress, forces and tangent scale with its stiffness factor: the weight
// is the tet's volume times that factor, and the Lame parameters are the material's.
struct Reference {
  std::vector<Matrix43> gradients;
  std::vector<double> weights;  // volume x stiffness factor, mm^3
  NodeGraph graph;
  std::vector<std::array<int, 16>> block_entries;  // entry of block (a, b) at 4 a + b
};

Reference reference_of(const TetMesh& mesh) {
  Reference r;
  r.gradients.reserve(size_t(mesh.tet_count()));
  r.weights.reserve(size_t(mesh.tet_count()));
  for (int t = 0; t < mesh.tet_count(); ++t) {
    r.gradients.push_back(shape_gradients(tet_corners(mesh, t)));
    r.weights.push_back(signed_volume(mesh, t) * mesh.stiffness_of(t));
  }
  return r;
}

void add_block_entries(const TetMesh& mesh, Reference& r) {
  r.graph = build_node_graph(mesh);
  r.block_entries.resize(size_t(mesh.tet_count()));
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        r.block_entries[size_t(t)][size_t(4 * a + b)] = r.graph.find(mesh.tets(t, a), mesh.tets(t, b));
}

Eigen::Matrix3d deformation_gradient(const TetMesh& mesh, int t, const Matrix43& g, const Eigen::MatrixX3d& u) {
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  for (int a = 0; a < 4; ++a) f += u.row(mesh.tets(t, a)).transpose() * g.row(a);
  return f;
}

Eigen::Matrix3d svk_stress(const Eigen::Matrix3d& e, const LameParameters& lame) {  // second Piola-Kirchhoff
  return lame.lambda * e.trace() * Eigen::Matrix3d::Identity() + 2 * lame.mu * e;
}

Eigen::Matrix3d green_lagrange(const Eigen::Matrix3d& f) {
  return 0.5 * (f.transpose() * f - Eigen::Matrix3d::Identity());
}

// First Piola-Kirchhoff stress; NaN for a neo-Hookean tet turned inside out (J <= 0), which
// the line search then refuses.
Eigen::Matrix3d first_piola(const Eigen::Matrix3d& F, const LameParameters& lame, HyperelasticLaw law) {
  if (law == HyperelasticLaw::kStVenantKirchhoff) return F * svk_stress(green_lagrange(F), lame);
  const double j = F.determinant();
  if (!(j > 0)) return Eigen::Matrix3d::Constant(std::numeric_limits<double>::quiet_NaN());
  return lame.mu * F + (lame.lambda * std::log(j) - lame.mu) * F.inverse().transpose();
}

Eigen::MatrixX3d forces(const TetMesh& mesh, const Reference& ref, const LameParameters& lame,
                        const Eigen::MatrixX3d& u, HyperelasticLaw law) {
  Eigen::MatrixX3d f = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  for (int t = 0; t < mesh.tet_count(); ++t) {
    const auto& g = ref.gradients[size_t(t)];
    const Eigen::Matrix3d F = deformation_gradient(mesh, t, g, u);
    const Eigen::Matrix3d P = first_piola(F, lame, law);
    for (int a = 0; a < 4; ++a)
      f.row(mesh.tets(t, a)) += ref.weights[size_t(t)] * (P * g.row(a).transpose()).transpose();
  }
  return f;
}

// One tet's neo-Hookean tangent blocks (nonlinear_fem.h gives the closed form).
void add_neo_hookean_blocks(const Matrix43& g, double v, const Eigen::Matrix3d& F, const LameParameters& lame,
                            const std::array<int, 16>& entries, StiffnessBlocks& k) {
  const double j = F.determinant();
  if (!(j > 0)) return;  // never reached by an accepted state: the line search refuses inverted tets
  const Eigen::Matrix<double, 3, 4> h = F.inverse().transpose() * g.transpose();  // column a: F^-T g_a
  const Eigen::Matrix<double, 4, 4> gg = g * g.transpose();
  const double c = lame.mu - lame.lambda * std::log(j);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      Eigen::Matrix3d block = lame.mu * gg(a, b) * Eigen::Matrix3d::Identity();
      block.noalias() += lame.lambda * h.col(a) * h.col(b).transpose();
      block.noalias() += c * h.col(b) * h.col(a).transpose();
      k.blocks[size_t(entries[size_t(4 * a + b)])] += v * block;
    }
}

// The tangent d f / d u as node blocks (the closed form is derived in nonlinear_fem.h).
// Rows and columns of constrained nodes are assembled too; the solver skips them.
void assemble_tangent(const TetMesh& mesh, const Reference& ref, const LameParameters& lame, const Eigen::MatrixX3d& u,
                      HyperelasticLaw law, StiffnessBlocks& k) {
  std::fill(k.blocks.begin(), k.blocks.end(), Eigen::Matrix3d::Zero());
  for (int t = 0; t < mesh.tet_count(); ++t) {
    const auto& g = ref.gradients[size_t(t)];
    const double v = ref.weights[size_t(t)];
    const Eigen::Matrix3d F = deformation_gradient(mesh, t, g, u);
    if (law == HyperelasticLaw::kNeoHookean) {
      add_neo_hookean_blocks(g, v, F, lame, ref.block_entries[size_t(t)], k);
      continue;
    }
    const Eigen::Matrix3d S = svk_stress(green_lagrange(F), lame);
    const Eigen::Matrix3d B = F * F.transpose();
    const Eigen::Matrix<double, 3, 4> Fg = F * g.transpose();  // column a: F g_a
    const Eigen::Matrix<double, 4, 4> gSg = g * S * g.transpose();
    const Eigen::Matrix<double, 4, 4> gg = g * g.transpose();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        Eigen::Matrix3d block = (gSg(a, b) * Eigen::Matrix3d::Identity() + lame.mu * gg(a, b) * B);
        block.noalias() += lame.lambda * Fg.col(a) * Fg.col(b).transpose();
        block.noalias() += lame.mu * Fg.col(b) * Fg.col(a).transpose();
        k.blocks[size_t(ref.block_entries[size_t(t)][size_t(4 * a + b)])] += v * block;
      }
  }
}

// Node-major 3 n vector of the forces in the free directions (none on constrained nodes, those
// across the normal on sliding ones).
Eigen::VectorXd free_residual(const Eigen::MatrixX3d& f, const BoundaryConditions& bc) {
  Eigen::VectorXd r(3 * f.rows());
  for (Eigen::Index i = 0; i < f.rows(); ++i) r.segment<3>(3 * i) = bc.free_part(int(i), f.row(i).transpose());
  return r;
}

void add_free_step(Eigen::MatrixX3d& u, const Eigen::VectorXd& du, double alpha, const BoundaryConditions& bc) {
  for (Eigen::Index i = 0; i < u.rows(); ++i)
    u.row(i) += alpha * bc.free_part(int(i), du.segment<3>(3 * i)).transpose();
}

constexpr int kMaxLinearIterations = 20000;

}  // namespace

Eigen::MatrixX3d internal_forces(const TetMesh& mesh, const Material& material, const Eigen::MatrixX3d& u,
                                 HyperelasticLaw law) {
  return forces(mesh, reference_of(mesh), lame_parameters(material), u, law);
}

StiffnessBlocks tangent_stiffness(const TetMesh& mesh, const Material& material, const Eigen::MatrixX3d& u,
                                  HyperelasticLaw law) {
  Reference ref = reference_of(mesh);
  add_block_entries(mesh, ref);
  StiffnessBlocks k;
  k.graph = ref.graph;
  k.blocks.assign(k.graph.neighbours.size(), Eigen::Matrix3d::Zero());
  assemble_tangent(mesh, ref, lame_parameters(material), u, law, k);
  return k;
}

NonlinearSolution solve_nonlinear_static(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
                                         const NewtonOptions& options) {
  Reference ref = reference_of(mesh);
  add_block_entries(mesh, ref);
  const LameParameters lame = lame_parameters(material);
  StiffnessBlocks k;  // the tangent, re-assembled in place at every Newton step
  k.graph = ref.graph;
  k.blocks.assign(k.graph.neighbours.size(), Eigen::Matrix3d::Zero());
  auto newton_direction = [&](const Eigen::MatrixX3d& u, const Eigen::VectorXd& rhs, NonlinearSolution& solution) {
    assemble_tangent(mesh, ref, lame, u, options.law, k);
    BlockPcgResult pcg = solve_free_block_pcg(k, bc, rhs, options.linear_tolerance, kMaxLinearIterations);
    solution.linear_iterations += pcg.iterations;
    return pcg.x;
  };

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
    const Eigen::MatrixX3d f0 = forces(mesh, ref, lame, solution.displacement, options.law);
    constexpr double kEpsilon = 1e-4;
    const Eigen::VectorXd coupling =
        (free_residual(forces(mesh, ref, lame, solution.displacement + kEpsilon * increment, options.law), bc) -
         free_residual(f0, bc)) /
        kEpsilon;
    const Eigen::VectorXd r0 = free_residual(f0, bc);
    if (reference_norm == 0) reference_norm = std::max((r0 + coupling).norm(), 1e-300);
    const Eigen::VectorXd predictor = newton_direction(solution.displacement, -(r0 + coupling), solution);
    // The predicted free move is shortened while it turns a tet inside out (neo-Hookean: NaN forces).
    const Eigen::MatrixX3d start = solution.displacement + increment;
    Eigen::VectorXd r;
    for (double scale = 1; scale > 1e-3; scale /= 2) {
      solution.displacement = start;
      add_free_step(solution.displacement, predictor, scale, bc);
      r = free_residual(forces(mesh, ref, lame, solution.displacement, options.law), bc);
      if (r.allFinite()) break;
    }
    solution.converged = false;
    for (int it = 0; it < options.max_iterations_per_step; ++it) {
      solution.relative_residual = r.norm() / reference_norm;
      if (solution.relative_residual <= options.relative_tolerance) {
        solution.converged = true;
        break;
      }
      const Eigen::VectorXd du = newton_direction(solution.displacement, -r, solution);
      ++solution.newton_iterations;
      // Backtracking: halve the step until the residual decreases (Newton may overshoot).
      double alpha = 1;
      Eigen::MatrixX3d trial;
      Eigen::VectorXd trial_r;
      bool decreased = false;
      for (int halving = 0; halving < 8 && !decreased; ++halving, alpha /= 2) {
        trial = solution.displacement;
        add_free_step(trial, du, alpha, bc);
        trial_r = free_residual(forces(mesh, ref, lame, trial, options.law), bc);
        decreased = trial_r.allFinite() && trial_r.norm() < r.norm();  // NaN: a tet turned inside out
      }
      if (!trial_r.allFinite()) break;  // stalled: every step along the Newton direction inverts a tet
      solution.displacement = trial;    // (not decreased: the smallest step, as a nudge out of a plateau)
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
