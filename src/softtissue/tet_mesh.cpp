#include "softtissue/tet_mesh.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>

namespace maxillo::softtissue {

Eigen::Matrix<double, 4, 3> tet_corners(const TetMesh& mesh, int t) {
  Eigen::Matrix<double, 4, 3> corners;
  for (int a = 0; a < 4; ++a) corners.row(a) = mesh.nodes.row(mesh.tets(t, a));
  return corners;
}

double signed_volume(const TetMesh& mesh, int t) {
  Eigen::Matrix<double, 4, 3> p = tet_corners(mesh, t);
  Eigen::Matrix3d edges;
  edges << (p.row(1) - p.row(0)).transpose(), (p.row(2) - p.row(0)).transpose(), (p.row(3) - p.row(0)).transpose();
  return edges.determinant() / 6.0;
}

int orient_positively(TetMesh& mesh) {
  int flipped = 0;
  for (int t = 0; t < mesh.tet_count(); ++t) {
    if (signed_volume(mesh, t) < 0) {
      std::swap(mesh.tets(t, 2), mesh.tets(t, 3));
      ++flipped;
    }
  }
  return flipped;
}

int count_non_positive_tets(const TetMesh& mesh) {
  int count = 0;
  for (int t = 0; t < mesh.tet_count(); ++t) count += signed_volume(mesh, t) <= 0 ? 1 : 0;
  return count;
}

int NodeGraph::find(int i, int j) const {
  auto begin = neighbours.begin() + row_begin(i), end = neighbours.begin() + row_end(i);
  auto it = std::lower_bound(begin, end, j);
  assert(it != end && *it == j && "NodeGraph::find: nodes are not neighbours");
  return int(it - neighbours.begin());
}

NodeGraph build_node_graph(const TetMesh& mesh) {
  const int n = mesh.node_count();
  // Each tet gives every corner 4 entries (itself and 3 others); duplicates removed per row.
  std::vector<int> count(size_t(n) + 1, 0);
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int a = 0; a < 4; ++a) count[size_t(mesh.tets(t, a)) + 1] += 4;
  for (int i = 0; i < n; ++i) count[size_t(i) + 1] += count[size_t(i)] + 1;  // + self for isolated nodes
  std::vector<int> raw(static_cast<size_t>(count[size_t(n)]));
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (int i = 0; i < n; ++i) raw[size_t(fill[size_t(i)]++)] = i;
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) raw[size_t(fill[size_t(mesh.tets(t, a))]++)] = mesh.tets(t, b);
  NodeGraph graph;
  graph.offsets.assign(size_t(n) + 1, 0);
  graph.neighbours.reserve(raw.size() / 3);
  for (int i = 0; i < n; ++i) {
    auto begin = raw.begin() + count[size_t(i)], end = raw.begin() + count[size_t(i) + 1];
    std::sort(begin, end);
    auto last = std::unique(begin, end);
    graph.neighbours.insert(graph.neighbours.end(), begin, last);
    graph.offsets[size_t(i) + 1] = int(graph.neighbours.size());
  }
  return graph;
}

}  // namespace maxillo::softtissue
