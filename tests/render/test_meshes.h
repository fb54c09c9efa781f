#pragma once
// Small analytic meshes for render tests (LPS mm, counter-clockwise seen from outside).
#include <cmath>
#include <numbers>

#include "core/triangle_mesh.h"

namespace maxillo::render::testing {

// A latitude-longitude sphere with `rings` x `segments` quads split into triangles
// (2 * segments * (rings - 1) triangles).
inline TriangleMesh uv_sphere(const Eigen::Vector3d& centre, double radius, int rings, int segments) {
  TriangleMesh mesh;
  mesh.vertices.resize(2 + (rings - 1) * segments, 3);
  mesh.vertices.row(0) = (centre + Eigen::Vector3d(0, 0, radius)).transpose();
  mesh.vertices.row(1) = (centre - Eigen::Vector3d(0, 0, radius)).transpose();
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = std::numbers::pi * r / rings, phi = 2 * std::numbers::pi * s / segments;
      mesh.vertices.row(2 + (r - 1) * segments + s) =
          (centre +
           radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)))
              .transpose();
    }
  auto ring_vertex = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
  mesh.faces.resize(2 * segments * (rings - 1), 3);
  int f = 0;
  for (int s = 0; s < segments; ++s) {
    mesh.faces.row(f++) << 0, ring_vertex(1, s), ring_vertex(1, s + 1);
    mesh.faces.row(f++) << 1, ring_vertex(rings - 1, s + 1), ring_vertex(rings - 1, s);
  }
  for (int r = 1; r < rings - 1; ++r)
    for (int s = 0; s < segments; ++s) {
      mesh.faces.row(f++) << ring_vertex(r, s), ring_vertex(r + 1, s), ring_vertex(r + 1, s + 1);
      mesh.faces.row(f++) << ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r, s + 1);
    }
  return mesh;
}

// An axis-aligned box from min to max, 12 triangles.
inline TriangleMesh box(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  TriangleMesh mesh;
  mesh.vertices.resize(8, 3);
  for (int c = 0; c < 8; ++c)
    mesh.vertices.row(c) << ((c & 1) ? max.x() : min.x()), ((c & 2) ? max.y() : min.y()), ((c & 4) ? max.z() : min.z());
  mesh.faces.resize(12, 3);
  mesh.faces << 0, 2, 3, 0, 3, 1,  // -z
      4, 5, 7, 4, 7, 6,            // +z
      0, 1, 5, 0, 5, 4,            // -y
      2, 6, 7, 2, 7, 3,            // +y
      0, 4, 6, 0, 6, 2,            // -x
      1, 3, 7, 1, 7, 5;            // +x
  return mesh;
}

}  // namespace maxillo::render::testing
