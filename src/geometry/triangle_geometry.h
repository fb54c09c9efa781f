#pragma once
// Exact-predicate geometry of single triangles, the building blocks of the collision and
// distance queries. Coordinates in any common frame, millimetres.
#include <Eigen/Geometry>

namespace maxillo {

struct Triangle {
  Eigen::Vector3d a, b, c;
};

// True when the two closed triangles share at least one point (touching counts). Separating
// axis test over 17 candidate axes: both normals, the 9 edge-edge cross products and the 6
// in-plane edge normals, so coplanar and degenerate (needle, zero-area) triangles are handled
// by the same code path. Zero-length axes are skipped; they can never separate.
bool triangles_intersect(const Triangle& p, const Triangle& q);

// Which feature of the triangle the closest point lies on (for the sign of a distance:
// each feature has its own pseudo-normal).
enum class TriangleFeature { Face, EdgeAB, EdgeBC, EdgeCA, VertexA, VertexB, VertexC };

struct ClosestPoint {
  Eigen::Vector3d point;
  TriangleFeature feature = TriangleFeature::Face;
};

// The point of the closed triangle nearest to `p` (Ericson, Real-Time Collision Detection 5.1.5).
ClosestPoint closest_point_on_triangle(const Eigen::Vector3d& p, const Triangle& t);

}  // namespace maxillo
