#include "softtissue/block_pcg.h"

#include <Eigen/LU>
#include <cmath>
#include <vector>

namespace maxillo::softtissue {
namespace {

using Vector = Eigen::VectorXd;  // 3 n, node-major: entries 3 i .. 3 i + 2 belong to node i

// y = K_ff x on the free nodes (rows and columns of constrained nodes left out; their y is 0).
void multiply_free(const StiffnessBlocks& k, const std::vector<char>& is_free, const Vector& x, Vector& y) {
  const int n = k.node_count();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    if (is_free[size_t(i)])
      for (int e = k.graph.row_begin(i); e < k.graph.row_end(i); ++e) {
        const int j = k.graph.neighbours[size_t(e)];
        if (is_free[size_t(j)]) sum.noalias() += k.blocks[size_t(e)] * x.segment<3>(3 * j);
      }
    y.segment<3>(3 * i) = sum;
  }
}

// b = -K_fc u_c: the load of the imposed displacements on the free nodes.
Vector imposed_load(const StiffnessBlocks& k, const std::vector<char>& is_free, const BoundaryConditions& bc) {
  Vector b = Vector::Zero(3 * k.node_count());
  for (int i = 0; i < k.node_count(); ++i) {
    if (!is_free[size_t(i)]) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int e = k.graph.row_begin(i); e < k.graph.row_end(i); ++e) {
      const int j = k.graph.neighbours[size_t(e)];
      if (bc.constraint[size_t(j)] == NodeConstraint::kPrescribed) sum -= k.blocks[size_t(e)] * bc.displacement.row(j).transpose();
    }
    b.segment<3>(3 * i) = sum;
  }
  return b;
}

// Inverses of the free nodes' diagonal blocks.
std::vector<Eigen::Matrix3d> block_jacobi(const StiffnessBlocks& k, const std::vector<char>& is_free) {
  std::vector<Eigen::Matrix3d> inverse(size_t(k.node_count()), Eigen::Matrix3d::Zero());
  for (int i = 0; i < k.node_count(); ++i)
    if (is_free[size_t(i)]) inverse[size_t(i)] = k.blocks[size_t(k.graph.find(i, i))].inverse();
  return inverse;
}

void precondition(const std::vector<Eigen::Matrix3d>& inverse, const Vector& r, Vector& z) {
  const int n = int(inverse.size());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) z.segment<3>(3 * i) = inverse[size_t(i)] * r.segment<3>(3 * i);
}

}  // namespace

StaticSolution solve_block_pcg(const StiffnessBlocks& k, const BoundaryConditions& bc, const KrylovOptions& options) {
  const int n = k.node_count();
  std::vector<char> is_free(static_cast<size_t>(n), 0);
  for (int i = 0; i < n; ++i) is_free[size_t(i)] = bc.is_free(i);
  const Vector b = imposed_load(k, is_free, bc);
  const auto inverse = block_jacobi(k, is_free);

  StaticSolution solution;
  Vector x = Vector::Zero(3 * n), r = b, z(3 * n), p(3 * n), q(3 * n);
  const double b_norm = b.norm();
  if (b_norm == 0) {  // nothing imposed: the rest position
    solution.status = SolveStatus::kConverged;
  } else {
    precondition(inverse, r, z);
    p = z;
    double rz = r.dot(z);
    for (solution.iterations = 0; solution.iterations < options.max_iterations; ++solution.iterations) {
      solution.relative_residual = r.norm() / b_norm;
      if (solution.relative_residual <= options.relative_tolerance) {
        solution.status = SolveStatus::kConverged;
        break;
      }
      multiply_free(k, is_free, p, q);
      const double alpha = rz / p.dot(q);
      x.noalias() += alpha * p;
      r.noalias() -= alpha * q;
      precondition(inverse, r, z);
      const double rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
  }
  solution.displacement = initial_displacement(bc);
  for (int i = 0; i < n; ++i)
    if (is_free[size_t(i)]) solution.displacement.row(i) = x.segment<3>(3 * i).transpose();
  return solution;
}

}  // namespace maxillo::softtissue
