#include "softtissue/gaussian_mapping.h"

#include <algorithm>
#include <deque>

#include "geometry/aabb_tree.h"
#include "softtissue/tet_boundary.h"

namespace maxillo::softtissue {
namespace {

constexpr double kMinDistanceMm = 1e-6;  // a matched vertex itself gets a finite, dominant weight

// Vertex adjacency of a triangle mesh in compressed rows (each edge seen from both ends).
void vertex_adjacency(const TriangleMesh& mesh, std::vector<int>& offsets, std::vector<int>& neighbours) {
  const auto n = size_t(mesh.vertex_count());
  std::vector<std::vector<int>> lists(n);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      lists[size_t(mesh.faces(f, c))].push_back(mesh.faces(f, (c + 1) % 3));
      lists[size_t(mesh.faces(f, (c + 1) % 3))].push_back(mesh.faces(f, c));
    }
  offsets.assign(1, 0);
  neighbours.clear();
  for (auto& list : lists) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    neighbours.insert(neighbours.end(), list.begin(), list.end());
    offsets.push_back(int(neighbours.size()));
  }
}

// The skin vertex closest to p: the nearest vertex of the nearest skin triangle.
int closest_vertex(const AabbTree& tree, const TriangleMesh& skin, const Eigen::Vector3d& p, double reach) {
  const auto nearest = tree.nearest(p, reach);
  if (nearest.face < 0) return -1;
  int best = -1;
  double best_distance = 1e300;
  for (int c = 0; c < 3; ++c) {
    const int v = skin.faces(nearest.face, c);
    const double d = (skin.vertices.row(v).transpose() - p).squaredNorm();
    if (d < best_distance) best = v, best_distance = d;
  }
  return best;
}

}  // namespace

SkinIndex::SkinIndex(const TriangleMesh& mesh) : skin(&mesh), tree(mesh) {
  vertex_adjacency(mesh, offsets, neighbours);
}

GaussianMapping init_gaussian_mapping(const TetMesh& mesh, const TriangleMesh& skin, const GaussianMappingOptions& o) {
  return init_gaussian_mapping(mesh, tet_boundary(mesh), SkinIndex(skin), o);
}

GaussianMapping init_gaussian_mapping(const TetMesh& mesh, const TetBoundary& boundary, const SkinIndex& index,
                                      const GaussianMappingOptions& o) {
  const TriangleMesh& skin = *index.skin;
  const auto skin_count = int(skin.vertex_count());
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<int> hops(size_t(skin_count), -1);  // BFS depth, reset after each search
  std::vector<int> visited;
  for (int node : boundary.nodes) {
    const int matched = closest_vertex(index.tree, skin, mesh.nodes.row(node).transpose(), o.max_match_distance_mm);
    if (matched < 0) continue;
    const Eigen::Vector3d pj = skin.vertices.row(matched).transpose();
    // Breadth-first from P_j over the skin: every P_i within the hop and radius limits gets
    // weight 1 / d_ij from this node (the relation is symmetric, so searching from P_j finds
    // exactly the P_i whose neighbourhood holds P_j).
    std::deque<int> queue{matched};
    hops[size_t(matched)] = 0;
    visited.assign(1, matched);
    while (!queue.empty()) {
      const int i = queue.front();
      queue.pop_front();
      const double d = (skin.vertices.row(i).transpose() - pj).norm();
      entries.emplace_back(i, node, 1.0 / std::max(d, kMinDistanceMm));
      if (hops[size_t(i)] + 1 > o.max_hops) continue;
      for (int e = index.offsets[size_t(i)]; e < index.offsets[size_t(i) + 1]; ++e) {
        const int k = index.neighbours[size_t(e)];
        if (hops[size_t(k)] >= 0 || (skin.vertices.row(k).transpose() - pj).norm() > o.radius_mm) continue;
        hops[size_t(k)] = hops[size_t(i)] + 1;
        visited.push_back(k);
        queue.push_back(k);
      }
    }
    for (int v : visited) hops[size_t(v)] = -1;
  }
  GaussianMapping mapping;
  mapping.weights.resize(skin_count, mesh.node_count());
  mapping.weights.setFromTriplets(entries.begin(), entries.end());  // duplicates (shared P_j) add up
  for (int i = 0; i < skin_count; ++i) {
    double sum = 0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(mapping.weights, i); it; ++it)
      sum += it.value();
    if (sum <= 0) continue;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(mapping.weights, i); it; ++it)
      it.valueRef() /= sum;
    ++mapping.bound_count;
  }
  return mapping;
}

Eigen::MatrixX3d map_displacement(const GaussianMapping& mapping, const Eigen::MatrixX3d& node_displacement) {
  return mapping.weights * node_displacement;
}

}  // namespace maxillo::softtissue
