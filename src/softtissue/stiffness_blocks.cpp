#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {

StiffnessBlocks assemble_stiffness_blocks(const TetMesh& mesh, const Material& material) {
  StiffnessBlocks stiffness;
  stiffness.graph = build_node_graph(mesh);
  stiffness.blocks.assign(stiffness.graph.neighbours.size(), Eigen::Matrix3d::Zero());
  for (int t = 0; t < mesh.tet_count(); ++t) {
    const Eigen::Matrix<double, 12, 12> k =
        element_stiffness(tet_corners(mesh, t), scaled(material, mesh.stiffness_of(t)));
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        int entry = stiffness.graph.find(mesh.tets(t, a), mesh.tets(t, b));
        stiffness.blocks[size_t(entry)] += k.block<3, 3>(3 * a, 3 * b);
      }
  }
  return stiffness;
}

Eigen::SparseMatrix<double> to_sparse_matrix(const StiffnessBlocks& stiffness) {
  const int n = stiffness.node_count();
  Eigen::SparseMatrix<double> k(3 * n, 3 * n);
  k.reserve(Eigen::VectorXi::Constant(3 * n, 0) + Eigen::VectorXi::NullaryExpr(3 * n, [&](Eigen::Index d) {
              int i = int(d / 3);
              return 3 * (stiffness.graph.row_end(i) - stiffness.graph.row_begin(i));
            }));
  // K is symmetric, so column 3 j + c of K holds row 3 j + c: block(j, i) transposed.
  for (int j = 0; j < n; ++j)
    for (int e = stiffness.graph.row_begin(j); e < stiffness.graph.row_end(j); ++e) {
      int i = stiffness.graph.neighbours[size_t(e)];
      const Eigen::Matrix3d& block = stiffness.blocks[size_t(e)];  // block(j, i)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) k.insert(3 * i + r, 3 * j + c) = block(c, r);
    }
  k.makeCompressed();
  return k;
}

Eigen::MatrixX3d multiply(const StiffnessBlocks& stiffness, const Eigen::MatrixX3d& u) {
  Eigen::MatrixX3d f(u.rows(), 3);
  for (int i = 0; i < stiffness.node_count(); ++i) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int e = stiffness.graph.row_begin(i); e < stiffness.graph.row_end(i); ++e)
      sum += stiffness.blocks[size_t(e)] * u.row(stiffness.graph.neighbours[size_t(e)]).transpose();
    f.row(i) = sum.transpose();
  }
  return f;
}

}  // namespace maxillo::softtissue
