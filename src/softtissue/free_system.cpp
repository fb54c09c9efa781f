#include "softtissue/free_system.h"

#include <algorithm>
#include <cassert>

#include "core/error.h"

namespace maxillo::softtissue {

FreeNodeNumbering number_free_nodes(const std::vector<NodeConstraint>& constraint) {
  if (std::find(constraint.begin(), constraint.end(), NodeConstraint::kSliding) != constraint.end())
    throw Error(ErrorCode::kBadValue, "linear FEM",
                "the assembled free system has no sliding nodes; solve them with the block conjugate gradient");
  FreeNodeNumbering numbering;
  numbering.free_index.assign(constraint.size(), -1);
  for (size_t i = 0; i < constraint.size(); ++i)
    if (constraint[i] == NodeConstraint::kFree) {
      numbering.free_index[i] = numbering.free_count();
      numbering.free_nodes.push_back(int(i));
    }
  return numbering;
}

Eigen::SparseMatrix<double> free_free_matrix(const StiffnessBlocks& stiffness, const FreeNodeNumbering& numbering) {
  const int nf = numbering.free_count();
  std::vector<int> column_sizes(size_t(3 * nf));
  for (int f = 0; f < nf; ++f) {
    int j = numbering.free_nodes[size_t(f)], free_neighbours = 0;
    for (int e = stiffness.graph.row_begin(j); e < stiffness.graph.row_end(j); ++e)
      free_neighbours += numbering.free_index[size_t(stiffness.graph.neighbours[size_t(e)])] >= 0 ? 1 : 0;
    for (int c = 0; c < 3; ++c) column_sizes[size_t(3 * f + c)] = 3 * free_neighbours;
  }
  Eigen::SparseMatrix<double> k(3 * nf, 3 * nf);
  k.reserve(column_sizes);
  // Symmetry: column 3 g + c holds block(j, i)^T where j = free_nodes[g]; free numbers grow with
  // node numbers, so rows arrive in ascending order.
  for (int g = 0; g < nf; ++g) {
    int j = numbering.free_nodes[size_t(g)];
    for (int e = stiffness.graph.row_begin(j); e < stiffness.graph.row_end(j); ++e) {
      int f = numbering.free_index[size_t(stiffness.graph.neighbours[size_t(e)])];
      if (f < 0) continue;
      const Eigen::Matrix3d& block = stiffness.blocks[size_t(e)];
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) k.insert(3 * f + r, 3 * g + c) = block(c, r);
    }
  }
  k.makeCompressed();
  return k;
}

Eigen::VectorXd free_load(const StiffnessBlocks& stiffness, const FreeNodeNumbering& numbering,
                          const BoundaryConditions& bc) {
  assert(bc.node_count() == stiffness.node_count() && "free_load: conditions and mesh differ in node count");
  Eigen::VectorXd load = Eigen::VectorXd::Zero(3 * numbering.free_count());
  for (int f = 0; f < numbering.free_count(); ++f) {
    int i = numbering.free_nodes[size_t(f)];
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int e = stiffness.graph.row_begin(i); e < stiffness.graph.row_end(i); ++e) {
      int j = stiffness.graph.neighbours[size_t(e)];
      if (bc.constraint[size_t(j)] == NodeConstraint::kPrescribed)
        sum -= stiffness.blocks[size_t(e)] * bc.displacement.row(j).transpose();
    }
    load.segment<3>(3 * f) = sum;
  }
  return load;
}

Eigen::MatrixX3d assemble_displacement(const Eigen::VectorXd& free_solution, const FreeNodeNumbering& numbering,
                                       const BoundaryConditions& bc) {
  Eigen::MatrixX3d u = initial_displacement(bc);
  for (int f = 0; f < numbering.free_count(); ++f)
    u.row(numbering.free_nodes[size_t(f)]) = free_solution.segment<3>(3 * f).transpose();
  return u;
}

double max_free_force(const StiffnessBlocks& stiffness, const BoundaryConditions& bc, const Eigen::MatrixX3d& u) {
  Eigen::MatrixX3d f = multiply(stiffness, u);
  double largest = 0;
  for (int i = 0; i < bc.node_count(); ++i) largest = std::max(largest, bc.free_part(i, f.row(i).transpose()).norm());
  return largest;
}

}  // namespace maxillo::softtissue
