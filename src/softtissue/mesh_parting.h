#pragma once
// Tissues that touch without being joined: the upper and lower lip meet at the stomion and slide
// on each other, but a mesher that sees one block of soft tissue ties them node to node, so a
// maxilla brought forward drags the lower lip with it or tears the skin where they meet (issue
// 34). Parting a mesh undoes that tie along a surface: the faces between tetrahedra on opposite
// sides of it are no longer shared.
//
// A node on those faces gets one copy per group of its tetrahedra that still hang together
// through faces not parted: two copies inside the parting and where it reaches the mesh's
// boundary (the lips' front and the teeth behind them), one where the parting ends inside the
// tissue (the corners of the mouth, its front edge), so the mesh stays conforming there.
#include <Eigen/Core>
#include <functional>

#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct Parting {
  int faces = 0;        // faces no longer shared
  int added_nodes = 0;  // copies of the nodes on them
};

// Which side of a parting a point lies on: +1 or -1, 0 where nothing is parted.
using PartingSide = std::function<int(const Eigen::Vector3d&)>;

// Parts `mesh` along the interior faces shared by a tetrahedron whose centroid lies on side +1
// and one whose centroid lies on side -1. Copies are appended after the existing nodes (same
// position), in the order of the nodes they copy; the group of tetrahedra holding a node's
// lowest-numbered tetrahedron keeps the original. The result depends on the mesh alone, not on
// the order of any hash or thread.
Parting part_mesh(TetMesh& mesh, const PartingSide& side_of);

}  // namespace maxillo::softtissue
