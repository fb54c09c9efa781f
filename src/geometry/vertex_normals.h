#pragma once
// Unit normals at the vertices of a triangle mesh: the area-weighted mean of the normals of the faces around each
// vertex (faces counter-clockwise from outside, so normals point outwards).
#include "core/triangle_mesh.h"

namespace maxillo {

// One unit normal per vertex; a vertex on no face (or only degenerate ones) gets (0, 0, 0).
VertexMatrix vertex_normals(const TriangleMesh& mesh);

}  // namespace maxillo
