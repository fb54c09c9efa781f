#pragma once
// Measures and topology of a TriangleMesh (Eigen only, no VTK): area, enclosed volume,
// watertightness, connected components, outward orientation. Repairs: mesh_repair.h.
#include <cstdint>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo {

// Sum of triangle areas, mm^2.
double surface_area(const TriangleMesh& mesh);

// Signed enclosed volume by the divergence theorem, mm^3: positive when the faces are
// counter-clockwise seen from outside (normals out). Meaningful for closed surfaces only.
double signed_volume(const TriangleMesh& mesh);

struct EdgeCounts {
  int64_t boundary = 0;      // edges used by exactly one face (holes, open borders)
  int64_t non_manifold = 0;  // edges used by three or more faces
  int64_t inconsistent = 0;  // interior edges whose two faces traverse it in the same direction
};
EdgeCounts count_edges(const TriangleMesh& mesh);
// Closed, manifold and consistently oriented.
bool is_watertight(const TriangleMesh& mesh);

// Connected components through shared vertices: a label per face (0 = the component with the
// most faces, 1 = the next, ...), and the face count of each component in that order.
struct Components {
  std::vector<int> face_label;
  std::vector<int64_t> face_counts;
};
Components connected_components(const TriangleMesh& mesh);

// Keeps the `count` largest components (all when count <= 0), dropping any component with
// fewer than min_fraction x the faces of the largest. Unused vertices are removed.
TriangleMesh keep_largest_components(const TriangleMesh& mesh, int count, double min_fraction = 0.0);

// Reverses every face when the signed volume is negative, so that normals point out.
void orient_outward(TriangleMesh& mesh);

}  // namespace maxillo
