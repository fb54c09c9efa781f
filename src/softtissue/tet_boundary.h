#pragma once
// The outer surface of a tet mesh: the triangles that belong to exactly one tet, oriented
// outwards, with the tet each came from.
#include <vector>

#include "core/triangle_mesh.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct TetBoundary {
  TriangleMesh surface;          // vertices = every mesh node (unused ones included), boundary faces
  std::vector<int> tet_of_face;  // the tet each boundary face belongs to
  std::vector<int> nodes;        // the nodes on the boundary, ascending
};

TetBoundary tet_boundary(const TetMesh& mesh);

}  // namespace maxillo::softtissue
