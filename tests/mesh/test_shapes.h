#pragma once
// Analytic shapes for mesh tests: a unit cube mesh and sphere volumes with known area/volume.
#include <cmath>

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

}  // namespace maxillo::testing
