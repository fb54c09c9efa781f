#include "softtissue/tet_boundary.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>

namespace maxillo::softtissue {
namespace {

// The faces of a positively oriented tet (a, b, c, d), each counter-clockwise seen from outside.
constexpr std::array<std::array<int, 3>, 4> kTetFaces = {{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

// A face's corner set packed in 64 bits (21 bits per sorted node index), so that all faces can
// be sorted as integers: equal keys are the two sides of an interior face.
uint64_t face_key(std::array<int, 3> corners) {
  std::sort(corners.begin(), corners.end());
  return (uint64_t(corners[0]) << 42) | (uint64_t(corners[1]) << 21) | uint64_t(corners[2]);
}

}  // namespace

TetBoundary tet_boundary(const TetMesh& mesh) {
  assert(mesh.node_count() < (1 << 21) && "tet_boundary: node indices must fit in 21 bits");
  struct Face {
    uint64_t key;
    int tet;
    int local;  // which of kTetFaces
  };
  std::vector<Face> faces;
  faces.reserve(size_t(4 * mesh.tet_count()));
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int f = 0; f < 4; ++f) {
      const auto& local = kTetFaces[size_t(f)];
      faces.push_back({face_key({mesh.tets(t, local[0]), mesh.tets(t, local[1]), mesh.tets(t, local[2])}), t, f});
    }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });

  TetBoundary boundary;
  boundary.surface.vertices = mesh.nodes;
  std::vector<std::array<int, 3>> kept;
  for (size_t i = 0; i < faces.size();) {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i == 1) {  // used by one tet only: on the boundary
      const auto& local = kTetFaces[size_t(faces[i].local)];
      const int t = faces[i].tet;
      kept.push_back({mesh.tets(t, local[0]), mesh.tets(t, local[1]), mesh.tets(t, local[2])});
      boundary.tet_of_face.push_back(t);
    }
    i = j;
  }
  boundary.surface.faces.resize(Eigen::Index(kept.size()), 3);
  std::vector<char> on_boundary(size_t(mesh.node_count()), 0);
  for (size_t f = 0; f < kept.size(); ++f)
    for (int c = 0; c < 3; ++c) {
      boundary.surface.faces(Eigen::Index(f), c) = kept[f][size_t(c)];
      on_boundary[size_t(kept[f][size_t(c)])] = 1;
    }
  for (int n = 0; n < mesh.node_count(); ++n)
    if (on_boundary[size_t(n)]) boundary.nodes.push_back(n);
  return boundary;
}

}  // namespace maxillo::softtissue
