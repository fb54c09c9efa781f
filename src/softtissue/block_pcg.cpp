#include "softtissue/block_pcg.h"

#include <Eigen/LU>
#include <cmath>
#include <vector>

namespace maxillo::softtissue {
namespace {

using Vector = Eigen::VectorXd;  // 3 n, node-major: entries 3 i .. 3 i + 2 belong to node i

// Below this many nodes a product takes well under a millisecond and the threads' barrier costs
// more than it saves; on a shared machine far more (the 9,261-node cube of the refinement tests
// solved 10x slower on 2 threads than on 1 with the cores busy).
constexpr int kParallelNodes = 15000;

// y = K_ff x on the free directions: the rows and columns of constrained nodes left out (their y
// is 0), a sliding node's row projected across its normal. x lies in the free directions.
void multiply_free(const StiffnessBlocks& k, const BoundaryConditions& bc, const Vector& x, Vector& y) {
  const int n = k.node_count();
#pragma omp parallel for schedule(static) if (n >= kParallelNodes)
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    if (bc.has_free_directions(i)) {
      for (int e = k.graph.row_begin(i); e < k.graph.row_end(i); ++e) {
        const int j = k.graph.neighbours[size_t(e)];
        if (bc.has_free_directions(j)) sum.noalias() += k.blocks[size_t(e)] * x.segment<3>(3 * j);
      }
      if (!bc.is_free(i)) sum = bc.free_part(i, sum);
    }
    y.segment<3>(3 * i) = sum;
  }
}

// b = -K_fc u_c: the load of the imposed displacements on the free directions.
Vector imposed_load(const StiffnessBlocks& k, const BoundaryConditions& bc) {
  Vector b = Vector::Zero(3 * k.node_count());
  for (int i = 0; i < k.node_count(); ++i) {
    if (!bc.has_free_directions(i)) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int e = k.graph.row_begin(i); e < k.graph.row_end(i); ++e) {
      const int j = k.graph.neighbours[size_t(e)];
      if (!bc.is_free(j)) sum -= k.blocks[size_t(e)] * bc.imposed(j);
    }
    b.segment<3>(3 * i) = bc.free_part(i, sum);
  }
  return b;
}

// Inverses of the diagonal blocks restricted to each node's free directions.
std::vector<Eigen::Matrix3d> block_jacobi(const StiffnessBlocks& k, const BoundaryConditions& bc) {
  std::vector<Eigen::Matrix3d> inverse(size_t(k.node_count()), Eigen::Matrix3d::Zero());
  for (int i = 0; i < k.node_count(); ++i)
    if (bc.has_free_directions(i)) inverse[size_t(i)] = bc.restricted_inverse(i, k.blocks[size_t(k.graph.find(i, i))]);
  return inverse;
}

void precondition(const std::vector<Eigen::Matrix3d>& inverse, const Vector& r, Vector& z) {
  const int n = int(inverse.size());
#pragma omp parallel for schedule(static) if (n >= kParallelNodes)
  for (int i = 0; i < n; ++i) z.segment<3>(3 * i) = inverse[size_t(i)] * r.segment<3>(3 * i);
}

}  // namespace

BlockPcgResult solve_free_block_pcg(const StiffnessBlocks& k, const BoundaryConditions& free_directions,
                                    const Vector& b_in, double relative_tolerance, int max_iterations,
                                    bool stop_at_negative_curvature) {
  const int n = k.node_count();
  Vector b(3 * n);
  for (int i = 0; i < n; ++i) b.segment<3>(3 * i) = free_directions.free_part(i, b_in.segment<3>(3 * i));
  const auto inverse = block_jacobi(k, free_directions);
  BlockPcgResult result;
  result.x = Vector::Zero(3 * n);
  const double b_norm = b.norm();
  if (b_norm == 0) {  // nothing to move: x = 0 is exact
    result.converged = true;
    return result;
  }
  // A right-hand side with NaN (the non-linear FEM's forces on a tet turned inside out) has no
  // answer: every iteration would stay NaN up to the limit (20,000 on the cadaver's face, a
  // minute for nothing).
  if (!std::isfinite(b_norm)) {
    result.relative_residual = b_norm;
    return result;
  }
  Vector r = b, z(3 * n), p(3 * n), q(3 * n);
  precondition(inverse, r, z);
  p = z;
  double rz = r.dot(z);
  for (result.iterations = 0; result.iterations < max_iterations; ++result.iterations) {
    result.relative_residual = r.norm() / b_norm;
    if (result.relative_residual <= relative_tolerance) {
      result.converged = true;
      break;
    }
    multiply_free(k, free_directions, p, q);
    const double curvature = p.dot(q);
    if (stop_at_negative_curvature && curvature <= 0) {
      result.negative_curvature = true;
      if (result.iterations == 0) result.x = p;  // the preconditioned right-hand side
      break;
    }
    const double alpha = rz / curvature;
    result.x.noalias() += alpha * p;
    r.noalias() -= alpha * q;
    precondition(inverse, r, z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  if (!result.converged) result.relative_residual = r.norm() / b_norm;
  return result;
}

StaticSolution solve_block_pcg(const StiffnessBlocks& k, const BoundaryConditions& bc, const KrylovOptions& options) {
  const int n = k.node_count();
  const BlockPcgResult pcg =
      solve_free_block_pcg(k, bc, imposed_load(k, bc), options.relative_tolerance, options.max_iterations);
  StaticSolution solution;
  solution.status = pcg.converged ? SolveStatus::kConverged : SolveStatus::kNotConverged;
  solution.iterations = pcg.iterations;
  solution.relative_residual = pcg.relative_residual;
  solution.displacement = initial_displacement(bc);
  for (int i = 0; i < n; ++i)
    if (bc.has_free_directions(i)) solution.displacement.row(i) += pcg.x.segment<3>(3 * i).transpose();
  return solution;
}

}  // namespace maxillo::softtissue
