#include "softtissue/mesh_parting.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>
#include <vector>

namespace maxillo::softtissue {
namespace {

using FaceKey = std::array<int, 3>;  // a triangle's node indices, ascending

// The face of tet t opposite its corner `opposite`.
FaceKey face_of(const TetMesh& mesh, int t, int opposite) {
  FaceKey key{};
  int n = 0;
  for (int c = 0; c < 4; ++c)
    if (c != opposite) key[size_t(n++)] = mesh.tets(t, c);
  std::sort(key.begin(), key.end());
  return key;
}

// Every face of every tet with its tet, sorted by face: a face two tets share appears twice in a row.
std::vector<std::pair<FaceKey, int>> faces_with_tets(const TetMesh& mesh) {
  std::vector<std::pair<FaceKey, int>> faces;
  faces.reserve(size_t(mesh.tet_count()) * 4);
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int c = 0; c < 4; ++c) faces.emplace_back(face_of(mesh, t, c), t);
  std::sort(faces.begin(), faces.end());
  return faces;
}

// The interior faces between a tet on side +1 and one on side -1; sorted.
std::vector<FaceKey> parted_faces(const TetMesh& mesh, const PartingSide& side_of) {
  std::vector<int> side(size_t(mesh.tet_count()));
  for (int t = 0; t < mesh.tet_count(); ++t)
    side[size_t(t)] = side_of(tet_corners(mesh, t).colwise().mean().transpose());
  const auto faces = faces_with_tets(mesh);
  std::vector<FaceKey> parted;
  for (size_t i = 0; i + 1 < faces.size(); ++i) {
    if (faces[i].first != faces[i + 1].first) continue;
    if (side[size_t(faces[i].second)] * side[size_t(faces[i + 1].second)] < 0) parted.push_back(faces[i].first);
  }
  return parted;
}

// The tets around each node, in compressed rows, each row ascending.
struct NodeTets {
  std::vector<int> offsets, tets;
};

NodeTets tets_around_nodes(const TetMesh& mesh) {
  NodeTets around;
  around.offsets.assign(size_t(mesh.node_count()) + 1, 0);
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int c = 0; c < 4; ++c) ++around.offsets[size_t(mesh.tets(t, c)) + 1];
  std::partial_sum(around.offsets.begin(), around.offsets.end(), around.offsets.begin());
  around.tets.resize(size_t(around.offsets.back()));
  std::vector<int> next(around.offsets.begin(), around.offsets.end() - 1);
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int c = 0; c < 4; ++c) around.tets[size_t(next[size_t(mesh.tets(t, c))]++)] = t;
  return around;
}

int root_of(std::vector<int>& parent, int i) {
  while (parent[size_t(i)] != i) i = parent[size_t(i)] = parent[size_t(parent[size_t(i)])];
  return i;
}

// The groups of `tets` (all around `node`) that hang together through faces around the node that
// are not parted: the group number of each, 0 for the group holding tets[0].
std::vector<int> groups_around(const TetMesh& mesh, int node, const std::vector<int>& tets,
                               const std::vector<FaceKey>& parted) {
  std::vector<std::pair<FaceKey, int>> faces;  // the faces through `node`, with the local tet index
  for (size_t i = 0; i < tets.size(); ++i)
    for (int c = 0; c < 4; ++c)
      if (mesh.tets(tets[i], c) != node) faces.emplace_back(face_of(mesh, tets[i], c), int(i));
  std::sort(faces.begin(), faces.end());
  std::vector<int> parent(tets.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t f = 0; f + 1 < faces.size(); ++f)
    if (faces[f].first == faces[f + 1].first && !std::binary_search(parted.begin(), parted.end(), faces[f].first))
      parent[size_t(root_of(parent, faces[f].second))] = root_of(parent, faces[f + 1].second);
  // Number the groups by their first tet, so that tets[0]'s is 0.
  std::vector<int> number(tets.size(), -1), group(tets.size());
  int groups = 0;
  for (size_t i = 0; i < tets.size(); ++i) {
    int& n = number[size_t(root_of(parent, int(i)))];
    if (n < 0) n = groups++;
    group[i] = n;
  }
  return group;
}

}  // namespace

Parting part_mesh(TetMesh& mesh, const PartingSide& side_of) {
  const std::vector<FaceKey> parted = parted_faces(mesh, side_of);
  Parting result{int(parted.size()), 0};
  if (parted.empty()) return result;
  std::vector<int> nodes;
  for (const auto& face : parted) nodes.insert(nodes.end(), face.begin(), face.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());

  // Every group is found on the mesh as it was; the copies are made after.
  const NodeTets around = tets_around_nodes(mesh);
  struct Corner {
    int tet, node, copy;
  };
  std::vector<Corner> moved_corners;
  std::vector<int> copied;  // the node each copy copies, in the copies' order
  for (int node : nodes) {
    const std::vector<int> tets(around.tets.begin() + around.offsets[size_t(node)],
                                around.tets.begin() + around.offsets[size_t(node) + 1]);
    const std::vector<int> group = groups_around(mesh, node, tets, parted);
    const int first_copy = mesh.node_count() + int(copied.size()) - 1;  // group g > 0 gets first_copy + g
    const int groups = *std::max_element(group.begin(), group.end()) + 1;
    for (int g = 1; g < groups; ++g) copied.push_back(node);
    for (size_t i = 0; i < tets.size(); ++i)
      if (group[i] > 0) moved_corners.push_back({tets[i], node, first_copy + group[i]});
  }
  const int old_count = mesh.node_count();
  mesh.nodes.conservativeResize(old_count + Eigen::Index(copied.size()), 3);
  for (size_t c = 0; c < copied.size(); ++c) mesh.nodes.row(old_count + Eigen::Index(c)) = mesh.nodes.row(copied[c]);
  for (const auto& corner : moved_corners)
    for (int c = 0; c < 4; ++c)
      if (mesh.tets(corner.tet, c) == corner.node) mesh.tets(corner.tet, c) = corner.copy;
  result.added_nodes = int(copied.size());
  return result;
}

}  // namespace maxillo::softtissue
