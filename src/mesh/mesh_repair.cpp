// Surface repairs after decimation: duplicate faces, small holes, pinched vertices.
#include "mesh/mesh_repair.h"

#include <array>
#include <map>
#include <unordered_map>

#include "geometry/topology_helpers.h"

namespace maxillo {

using topology::edge_key;
using topology::UnionFind;

int64_t remove_duplicate_faces(TriangleMesh& mesh) {
  auto key_of = [&](Eigen::Index f) {
    std::array<int, 3> corners{mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)};
    std::sort(corners.begin(), corners.end());
    return corners;
  };
  std::map<std::array<int, 3>, int> uses;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) ++uses[key_of(f)];
  FaceMatrix kept(mesh.face_count(), 3);
  Eigen::Index count = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    if (uses[key_of(f)] == 1) kept.row(count++) = mesh.faces.row(f);
  const int64_t removed = mesh.face_count() - count;
  kept.conservativeResize(count, 3);
  mesh.faces = std::move(kept);
  return removed;
}

int64_t split_pinched_vertices(TriangleMesh& mesh) {
  std::unordered_map<uint64_t, int> edge_uses;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) ++edge_uses[edge_key(mesh.faces(f, c), mesh.faces(f, (c + 1) % 3))];
  // Faces around each vertex (compressed rows).
  std::vector<int> start(size_t(mesh.vertex_count()) + 1, 0), around(size_t(mesh.face_count()) * 3);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) ++start[size_t(mesh.faces(f, c)) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) around[size_t(fill[size_t(mesh.faces(f, c))]++)] = int(f);

  const FaceMatrix original = mesh.faces;
  std::vector<Eigen::RowVector3d> added;
  const int first_new = int(mesh.vertex_count());
  for (int v = 0; v < first_new; ++v) {
    const int begin = start[size_t(v)], end = start[size_t(v) + 1];
    if (end - begin < 2) continue;
    // Fans around v: faces joined through edges (v, w) that exactly two faces use.
    UnionFind fans(end - begin);
    for (int a = begin; a < end; ++a)
      for (int b = a + 1; b < end; ++b)
        for (int ca = 0; ca < 3; ++ca) {
          const int w = original(around[size_t(a)], ca);
          if (w == v || edge_uses[edge_key(v, w)] != 2) continue;
          const auto row_b = original.row(around[size_t(b)]);
          if (row_b(0) == w || row_b(1) == w || row_b(2) == w) fans.unite(a - begin, b - begin);
        }
    std::unordered_map<int, int> copy_of_fan;
    for (int a = begin; a < end; ++a) {
      const int fan = fans.find(a - begin);
      auto [it, first] = copy_of_fan.try_emplace(fan, v);
      if (first && copy_of_fan.size() > 1) {
        it->second = first_new + int(added.size());
        added.push_back(mesh.vertices.row(v));
      }
      for (int c = 0; c < 3; ++c)
        if (original(around[size_t(a)], c) == v) mesh.faces(around[size_t(a)], c) = it->second;
    }
  }
  mesh.vertices.conservativeResize(first_new + Eigen::Index(added.size()), 3);
  for (size_t n = 0; n < added.size(); ++n) mesh.vertices.row(first_new + Eigen::Index(n)) = added[n];
  return int64_t(added.size());
}

int64_t close_small_holes(TriangleMesh& mesh, int max_edges) {
  // A boundary edge a->b of a face is walked b->a by the hole; next[b] = a along the hole.
  std::unordered_map<uint64_t, int> uses;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) ++uses[edge_key(mesh.faces(f, c), mesh.faces(f, (c + 1) % 3))];
  std::unordered_map<int, std::vector<int>> next;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = mesh.faces(f, c), b = mesh.faces(f, (c + 1) % 3);
      if (uses[edge_key(a, b)] == 1) next[b].push_back(a);
    }
  std::vector<Eigen::Vector3i> added;
  std::unordered_map<int, bool> visited;
  int64_t closed = 0;
  for (const auto& [start, outgoing] : next) {
    if (visited[start]) continue;
    std::vector<int> loop{start};
    bool simple = true;
    for (int v = start;;) {
      visited[v] = true;
      auto it = next.find(v);
      if (it == next.end() || it->second.size() != 1) {
        simple = false;
        break;
      }
      v = it->second.front();
      if (v == start) break;
      if (visited[v] || int(loop.size()) >= max_edges) {
        simple = false;
        break;
      }
      loop.push_back(v);
    }
    if (!simple || loop.size() < 3) continue;
    for (size_t n = 1; n + 1 < loop.size(); ++n) added.emplace_back(loop[0], loop[n], loop[n + 1]);
    ++closed;
  }
  const Eigen::Index old_count = mesh.face_count();
  mesh.faces.conservativeResize(old_count + Eigen::Index(added.size()), 3);
  for (size_t n = 0; n < added.size(); ++n) mesh.faces.row(old_count + Eigen::Index(n)) = added[n].transpose();
  return closed;
}

}  // namespace maxillo
