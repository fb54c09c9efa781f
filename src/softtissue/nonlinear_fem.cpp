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

// Strain energy density W(F) of each law (nonlinear_fem.h); infinite for a neo-Hookean tet
// turned inside out.
double energy_density(const Eigen::Matrix3d& F, const LameParameters& lame, HyperelasticLaw law) {
  if (law == HyperelasticLaw::kStVenantKirchhoff) {
    const Eigen::Matrix3d e = green_lagrange(F);
    return 0.5 * lame.lambda * e.trace() * e.trace() + lame.mu * (e * e).trace();
  }
  const double j = F.determinant();
  if (!(j > 0)) return std::numeric_limits<double>::infinity();
  const double log_j = std::log(j);
  return 0.5 * lame.mu * ((F.transpose() * F).trace() - 3) - lame.mu * log_j + 0.5 * lame.lambda * log_j * log_j;
}

double strain_energy(const TetMesh& mesh, const Reference& ref, const LameParameters& lame, const Eigen::MatrixX3d& u,
                     HyperelasticLaw law) {
  double total = 0;
  for (int t = 0; t < mesh.tet_count(); ++t)
    total +=
        ref.weights[size_t(t)] * energy_density(deformation_gradient(mesh, t, ref.gradients[size_t(t)], u), lame, law);
  return total;
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

namespace {

// The state the load steps share: reference geometry, material, and the tangent's storage,
// re-assembled in place at every Newton step.
class NewtonSolver {
 public:
  NewtonSolver(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
               const NewtonOptions& options)
      : mesh_(mesh), bc_(bc), options_(options), ref_(reference_of(mesh)), lame_(lame_parameters(material)) {
    add_block_entries(mesh, ref_);
    k_.graph = ref_.graph;
    k_.blocks.assign(k_.graph.neighbours.size(), Eigen::Matrix3d::Zero());
  }

  // The free-direction residual at u; NaN where a neo-Hookean tet is inside out.
  Eigen::VectorXd residual(const Eigen::MatrixX3d& u) const {
    return free_residual(forces(mesh_, ref_, lame_, u, options_.law), bc_);
  }

  // One load step: the constrained nodes move on by `fraction` of their imposed displacement and
  // the free ones follow. Returns false, with u unchanged, when the step turns a tet inside out
  // or Newton does not reach the tolerance within its iterations.
  bool take_step(Eigen::MatrixX3d& u, double fraction, double& reference_norm, NonlinearSolution& solution) {
    // Predictor: the imposed increment moves the free nodes as the current tangent says,
    // K_ff du_f = -(r + K_fc du_c); jumping the constrained nodes alone would invert the tets
    // around them. K_fc du_c is the directional derivative of the forces (a finite difference).
    Eigen::MatrixX3d increment = Eigen::MatrixX3d::Zero(mesh_.node_count(), 3);
    for (int i = 0; i < mesh_.node_count(); ++i)
      if (!bc_.is_free(i)) increment.row(i) = fraction * bc_.imposed(i).transpose();
    constexpr double kEpsilon = 1e-4;
    const Eigen::VectorXd r0 = residual(u);
    const Eigen::VectorXd coupling = (residual(u + kEpsilon * increment) - r0) / kEpsilon;
    if (reference_norm == 0) reference_norm = std::max((r0 + coupling).norm(), 1e-300);
    Eigen::MatrixX3d trial = u + increment;
    add_free_step(trial, newton_direction(u, -(r0 + coupling), solution), 1, bc_);
    Eigen::VectorXd r = residual(trial);
    if (!r.allFinite()) return false;  // the increment is too large for the mesh: a tet inverts
    for (int it = 0; it < options_.max_iterations_per_step; ++it) {
      solution.relative_residual = r.norm() / reference_norm;
      if (solution.relative_residual <= options_.relative_tolerance) {
        u = trial;
        return true;
      }
      if (!newton_iteration(trial, r, solution)) return false;
    }
    solution.relative_residual = r.norm() / reference_norm;
    if (solution.relative_residual > options_.relative_tolerance) return false;
    u = trial;
    return true;
  }

 private:
  Eigen::VectorXd newton_direction(const Eigen::MatrixX3d& u, const Eigen::VectorXd& rhs, NonlinearSolution& solution,
                                   bool truncated = false) {
    assemble_tangent(mesh_, ref_, lame_, u, options_.law, k_);
    BlockPcgResult pcg = solve_free_block_pcg(k_, bc_, rhs, options_.linear_tolerance, kMaxLinearIterations, truncated);
    solution.linear_iterations += pcg.iterations;
    return pcg.x;
  }

  // One Newton step from u with residual r (the energy's gradient in the free directions), both
  // updated. The direction is the truncated conjugate gradient's (a descent direction even where
  // the tangent is indefinite: a compressed tissue near buckling, where plain Newton heads for a
  // saddle and stalls); the step is halved until the energy falls by a fraction of what its slope
  // promises (Armijo) or, near the answer where energy differences drown in round-off, until the
  // residual halves. False when no step along the direction does either.
  bool newton_iteration(Eigen::MatrixX3d& u, Eigen::VectorXd& r, NonlinearSolution& solution) {
    const Eigen::VectorXd du = newton_direction(u, -r, solution, /*truncated=*/true);
    ++solution.newton_iterations;
    const double slope = r.dot(du);
    if (!(slope < 0)) return false;
    const double energy = strain_energy(mesh_, ref_, lame_, u, options_.law);
    constexpr double kArmijo = 1e-4;
    double alpha = 1;
    for (int halving = 0; halving < kMaxHalvings; ++halving, alpha /= 2) {
      Eigen::MatrixX3d trial = u;
      add_free_step(trial, du, alpha, bc_);
      const double trial_energy = strain_energy(mesh_, ref_, lame_, trial, options_.law);
      if (!std::isfinite(trial_energy)) continue;  // a tet turned inside out
      const Eigen::VectorXd trial_r = residual(trial);
      if (trial_energy <= energy + kArmijo * alpha * slope || trial_r.norm() <= 0.5 * r.norm()) {
        u = trial;
        r = trial_r;
        return true;
      }
    }
    return false;
  }

  static constexpr int kMaxHalvings = 12;

  const TetMesh& mesh_;
  const BoundaryConditions& bc_;
  const NewtonOptions& options_;
  Reference ref_;
  LameParameters lame_;
  StiffnessBlocks k_;
};

}  // namespace

NonlinearSolution solve_nonlinear_static(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
                                         const NewtonOptions& options) {
  NewtonSolver solver(mesh, material, bc, options);
  NonlinearSolution solution;
  solution.displacement = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  // The tolerance is relative to the first step's residual, at the planned step size, so that
  // halving a step later does not tighten it.
  double reference_norm = 0;
  const double planned = 1.0 / std::max(options.load_steps, 1);
  double fraction = planned;
  double reached = 0;  // fraction of the imposed displacement applied and in equilibrium
  int successes_in_a_row = 0;
  while (reached < 1 - 1e-12) {
    fraction = std::min(fraction, 1 - reached);
    if (solver.take_step(solution.displacement, fraction, reference_norm, solution)) {
      reached += fraction;
      ++solution.load_steps;
      // After two easy steps the step grows back, never beyond the planned one.
      if (++successes_in_a_row >= 2) fraction = std::min(2 * fraction, planned);
      continue;
    }
    ++solution.rejected_steps;
    successes_in_a_row = 0;
    fraction /= 2;
    if (fraction < options.smallest_load_fraction) break;
  }
  solution.load_reached = std::min(reached, 1.0);
  solution.converged = reached >= 1 - 1e-12;
  if (!solution.converged && !std::isfinite(solution.relative_residual))
    solution.relative_residual = std::numeric_limits<double>::infinity();
  return solution;
}

}  // namespace maxillo::softtissue
