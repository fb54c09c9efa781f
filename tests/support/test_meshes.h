#pragma once
// Small meshes with known geometry for the occlusion tests.
#include <Eigen/Geometry>
#include <random>

#include "core/triangle_mesh.h"

namespace maxillo::testing {

// Closed axis-aligned box, outward normals, 12 triangles.
inline TriangleMesh make_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  TriangleMesh m;
  m.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    m.vertices.row(i) << ((i & 1) ? hi.x() : lo.x()), ((i & 2) ? hi.y() : lo.y()), ((i & 4) ? hi.z() : lo.z());
  m.faces.resize(12, 3);
  m.faces << 0, 2, 1, 1, 2, 3,  // z = lo
      4, 5, 6, 5, 7, 6,         // z = hi
      0, 1, 4, 1, 5, 4,         // y = lo
      2, 6, 3, 3, 6, 7,         // y = hi
      0, 4, 2, 2, 4, 6,         // x = lo
      1, 3, 5, 3, 7, 5;         // x = hi
  return m;
}

// Two meshes appended (vertex indices of the second shifted).
inline TriangleMesh append(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh m;
  m.vertices.resize(a.vertex_count() + b.vertex_count(), 3);
  m.vertices << a.vertices, b.vertices;
  m.faces.resize(a.face_count() + b.face_count(), 3);
  m.faces << a.faces, (b.faces.array() + int(a.vertex_count())).matrix();
  return m;
}

// A soup of `count` random triangles of size ~`size` in a cube of side `extent` (mm).
inline TriangleMesh random_soup(unsigned seed, int count, double extent, double size) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> where(0, extent), offset(-size, size);
  TriangleMesh m;
  m.vertices.resize(3 * count, 3);
  m.faces.resize(count, 3);
  for (int t = 0; t < count; ++t) {
    const Eigen::Vector3d c(where(rng), where(rng), where(rng));
    for (int k = 0; k < 3; ++k) {
      m.vertices.row(3 * t + k) = (c + Eigen::Vector3d(offset(rng), offset(rng), offset(rng))).transpose();
      m.faces(t, k) = 3 * t + k;
    }
  }
  return m;
}

inline Eigen::Isometry3d random_pose(std::mt19937& rng, double max_translation, double max_angle_rad) {
  std::uniform_real_distribution<double> unit(-1, 1);
  Eigen::Vector3d axis(unit(rng), unit(rng), unit(rng));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(max_translation * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
  pose.rotate(Eigen::AngleAxisd(max_angle_rad * unit(rng), axis.normalized()));
  return pose;
}

}  // namespace maxillo::testing
