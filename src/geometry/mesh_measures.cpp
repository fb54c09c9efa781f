// Mesh measures: closed-form sums over faces, union-find components, a hash of directed edges.
#include "geometry/mesh_measures.h"

#include "geometry/topology_helpers.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include <Eigen/Geometry>  // cross()

namespace maxillo {
namespace {

using topology::edge_key;
using topology::UnionFind;

Eigen::Vector3d corner(const TriangleMesh& mesh, Eigen::Index face, int c) {
  return mesh.vertices.row(mesh.faces(face, c)).transpose();
}

}  // namespace

double surface_area(const TriangleMesh& mesh) {
  double area = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    Eigen::Vector3d a = corner(mesh, f, 0), b = corner(mesh, f, 1), c = corner(mesh, f, 2);
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

double signed_volume(const TriangleMesh& mesh) {
  // Relative to the centroid of the vertices, which keeps the sum well conditioned far from 0.
  Eigen::Vector3d centre =
      mesh.vertex_count() ? Eigen::Vector3d(mesh.vertices.colwise().mean().transpose()) : Eigen::Vector3d::Zero();
  double volume = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    Eigen::Vector3d a = corner(mesh, f, 0) - centre, b = corner(mesh, f, 1) - centre, c = corner(mesh, f, 2) - centre;
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

EdgeCounts count_edges(const TriangleMesh& mesh) {
  struct Use {
    int count = 0;
    int forward = 0;
  };  // forward: traversed from smaller to larger index
  std::unordered_map<uint64_t, Use> edges;
  edges.reserve(size_t(mesh.face_count()) * 2);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      int a = mesh.faces(f, c), b = mesh.faces(f, (c + 1) % 3);
      Use& use = edges[edge_key(a, b)];
      ++use.count;
      if (a < b) ++use.forward;
    }
  EdgeCounts counts;
  for (const auto& [key, use] : edges) {
    if (use.count == 1)
      ++counts.boundary;
    else if (use.count > 2)
      ++counts.non_manifold;
    else if (use.forward != 1)
      ++counts.inconsistent;
  }
  return counts;
}

bool is_watertight(const TriangleMesh& mesh) {
  EdgeCounts counts = count_edges(mesh);
  return mesh.face_count() > 0 && counts.boundary == 0 && counts.non_manifold == 0 && counts.inconsistent == 0;
}

Components connected_components(const TriangleMesh& mesh) {
  UnionFind sets(mesh.vertex_count());
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    sets.unite(mesh.faces(f, 0), mesh.faces(f, 1));
    sets.unite(mesh.faces(f, 0), mesh.faces(f, 2));
  }
  std::unordered_map<int, int> root_to_raw;
  std::vector<int64_t> raw_counts;
  std::vector<int> raw_label(size_t(mesh.face_count()));
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    auto [it, added] = root_to_raw.try_emplace(sets.find(mesh.faces(f, 0)), int(raw_counts.size()));
    if (added) raw_counts.push_back(0);
    ++raw_counts[it->second];
    raw_label[f] = it->second;
  }
  std::vector<int> order(raw_counts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return raw_counts[a] > raw_counts[b]; });
  std::vector<int> rank(order.size());
  Components result;
  for (size_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = int(r);
    result.face_counts.push_back(raw_counts[order[r]]);
  }
  result.face_label.resize(raw_label.size());
  for (size_t f = 0; f < raw_label.size(); ++f) result.face_label[f] = rank[raw_label[f]];
  return result;
}

TriangleMesh keep_largest_components(const TriangleMesh& mesh, int count, double min_fraction) {
  Components components = connected_components(mesh);
  if (components.face_counts.empty()) return mesh;
  const double smallest_kept = min_fraction * double(components.face_counts.front());
  int kept = count <= 0 ? int(components.face_counts.size()) : std::min<int>(count, int(components.face_counts.size()));
  while (kept > 1 && double(components.face_counts[kept - 1]) < smallest_kept) --kept;

  std::vector<int> new_index(size_t(mesh.vertex_count()), -1);
  std::vector<Eigen::Index> kept_faces;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    if (components.face_label[f] < kept) kept_faces.push_back(f);
  TriangleMesh out;
  out.faces.resize(Eigen::Index(kept_faces.size()), 3);
  int vertices = 0;
  for (size_t n = 0; n < kept_faces.size(); ++n)
    for (int c = 0; c < 3; ++c) {
      int& index = new_index[mesh.faces(kept_faces[n], c)];
      if (index < 0) index = vertices++;
      out.faces(Eigen::Index(n), c) = index;
    }
  out.vertices.resize(vertices, 3);
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
    if (new_index[v] >= 0) out.vertices.row(new_index[v]) = mesh.vertices.row(v);
  return out;
}

void orient_outward(TriangleMesh& mesh) {
  if (signed_volume(mesh) < 0) mesh.faces.col(1).swap(mesh.faces.col(2));
}

}  // namespace maxillo
