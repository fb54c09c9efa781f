#pragma once
// Topology repairs for surfaces that came out of decimation (Eigen only, no VTK). Each keeps
// the vertex coordinates and returns how much it changed; together they turn a closed surface
// with a few decimation defects back into a closed, manifold, consistently oriented one.
#include <cstdint>

#include "core/triangle_mesh.h"

namespace maxillo {

// Removes every face whose three vertices are also those of another face (all copies): the
// double-sided "fins" decimation leaves where a thin tube collapsed. Returns faces removed.
int64_t remove_duplicate_faces(TriangleMesh& mesh);

// Closes holes bounded by at most max_edges boundary edges with a fan of triangles oriented
// like the faces around the hole. Holes whose border is not a simple loop are left open.
// Returns the number of holes closed.
int64_t close_small_holes(TriangleMesh& mesh, int max_edges = 8);

// Where two sheets of the surface touch along an edge or at a vertex, gives each sheet its
// own copy of the shared vertices, so every edge is used by at most two faces.
// Returns the number of vertices added.
int64_t split_pinched_vertices(TriangleMesh& mesh);

}  // namespace maxillo
