#pragma once
// Analytic shapes for mesh tests: a unit cube mesh and sphere volumes with known area/volume.
#include <cmath>
#include <vector>

#include "core/triangle_mesh.h"
#include "core/volume.h"

namespace maxillo::testing {

// Axis-aligned cube [0, side]^3, 12 triangles, counter-clockwise seen from outside.
inline TriangleMesh cube(double side = 1) {
  TriangleMesh m;
  m.vertices.resize(8, 3);
  for (int v = 0; v < 8; ++v) m.vertices.row(v) << side * (v & 1), side * ((v >> 1) & 1), side * ((v >> 2) & 1);
  m.faces.resize(12, 3);
  m.faces << 0, 2, 1, 1, 2, 3,  // z = 0, normal -z
      4, 5, 6, 5, 7, 6,         // z = 1, normal +z
      0, 1, 4, 1, 5, 4,         // y = 0, normal -y
      2, 6, 3, 3, 6, 7,         // y = 1, normal +y
      0, 4, 2, 2, 4, 6,         // x = 0, normal -x
      1, 3, 5, 3, 7, 5;         // x = 1, normal +x
  return m;
}

// A volume of `size`^3 voxels of 1 mm (then placed by direction/origin) whose HU falls linearly
// through 0 at distance `radius` from the centre voxel `centre_ijk`: HU = 100 (radius - d).
inline Volume sphere_volume(int size, const Eigen::Vector3d& centre_ijk, double radius,
                            const Eigen::Matrix3d& direction = Eigen::Matrix3d::Identity(),
                            const Eigen::Vector3d& origin = Eigen::Vector3d::Zero()) {
  Volume v;
  v.geometry.size = {size, size, size};
  v.geometry.direction = direction;
  v.geometry.origin = origin;
  v.hu.resize(size_t(v.geometry.voxel_count()));
  for (int k = 0; k < size; ++k)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        double d = (Eigen::Vector3d(i, j, k) - centre_ijk).norm();
        v.at(i, j, k) = int16_t(std::clamp(std::lround(100 * (radius - d)), -1000L, 1000L));
      }
  return v;
}

// A latitude-longitude sphere: `rings` bands between the poles, `segments` around; closed,
// counter-clockwise seen from outside. Every vertex lies exactly on the sphere.
inline TriangleMesh uv_sphere(const Eigen::Vector3d& centre, double radius, int rings = 24, int segments = 48) {
  TriangleMesh m;
  const int ring_vertices = (rings - 1) * segments;
  m.vertices.resize(ring_vertices + 2, 3);
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double polar = M_PI * r / rings, azimuth = 2 * M_PI * s / segments;
      const Eigen::Vector3d unit(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                                 std::cos(polar));
      m.vertices.row((r - 1) * segments + s) = (centre + radius * unit).transpose();
    }
  const int north = ring_vertices, south = ring_vertices + 1;
  m.vertices.row(north) = (centre + Eigen::Vector3d(0, 0, radius)).transpose();
  m.vertices.row(south) = (centre - Eigen::Vector3d(0, 0, radius)).transpose();
  std::vector<Eigen::Vector3i> faces;
  auto at = [&](int r, int s) { return (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    faces.emplace_back(north, at(1, s), at(1, s + 1));
    faces.emplace_back(south, at(rings - 1, s + 1), at(rings - 1, s));
    for (int r = 1; r + 1 < rings; ++r) {
      faces.emplace_back(at(r, s), at(r + 1, s), at(r + 1, s + 1));
      faces.emplace_back(at(r, s), at(r + 1, s + 1), at(r, s + 1));
    }
  }
  m.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) m.faces.row(Eigen::Index(f)) = faces[f].transpose();
  return m;
}

}  // namespace maxillo::testing
