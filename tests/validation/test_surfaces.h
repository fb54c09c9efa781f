#pragma once
// Closed test surfaces with known geometry: the zero set of a function sampled on a fine grid,
// triangulated by marching tetrahedra (below), so the vertices lie on the surface to within a
// few hundredths of a millimetre. Eigen only: the validation tests need no toolkit.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::validation::test {

// `inside_mm(p)`: positive inside, negative outside, ~ the distance to the surface near it.
// The grid covers the cube [-half_extent, half_extent]^3, a node every `spacing` mm. Each grid
// cube is split into the six tetrahedra around its main diagonal (the same split in every
// cube, so neighbouring cubes share their faces' triangulations), and each tetrahedron crossed
// by the surface gives one triangle or two. A vertex sits where the linear interpolation along
// a grid edge crosses zero and is shared by every cell around that edge, so the surface is
// closed; faces are turned so their normals point outwards.
inline TriangleMesh implicit_surface(const std::function<double(const Eigen::Vector3d&)>& inside_mm, double half_extent,
                                     double spacing = 1.0) {
  const int n = int(std::ceil(2 * half_extent / spacing)) + 1;
  const double origin = -(n - 1) * spacing / 2;
  auto node = [n](int i, int j, int k) { return (int64_t(k) * n + j) * n + i; };
  auto position = [&](int64_t id) {
    const int64_t i = id % n, j = (id / n) % n, k = id / (int64_t(n) * n);
    return Eigen::Vector3d(origin + double(i) * spacing, origin + double(j) * spacing, origin + double(k) * spacing);
  };
  std::vector<double> value(size_t(int64_t(n) * n * n));
  for (int64_t id = 0; id < int64_t(value.size()); ++id) {
    const double v = inside_mm(position(id));
    value[size_t(id)] = v == 0 ? -1e-12 : v;  // no vertex exactly on a node: no zero-area faces
  }

  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  std::unordered_map<int64_t, int> vertex_of_edge;
  auto edge_vertex = [&](int64_t in, int64_t out) {
    const int64_t key = std::min(in, out) * int64_t(value.size()) + std::max(in, out);
    auto [it, added] = vertex_of_edge.try_emplace(key, int(vertices.size()));
    if (added) {
      const double t = value[size_t(in)] / (value[size_t(in)] - value[size_t(out)]);
      vertices.push_back(position(in) + t * (position(out) - position(in)));
    }
    return it->second;
  };
  auto add_face = [&](int a, int b, int c, const Eigen::Vector3d& outward) {
    const Eigen::Vector3d normal =
        (vertices[size_t(b)] - vertices[size_t(a)]).cross(vertices[size_t(c)] - vertices[size_t(a)]);
    if (normal.dot(outward) >= 0)
      faces.emplace_back(a, b, c);
    else
      faces.emplace_back(a, c, b);
  };
  // The six tetrahedra of a cube around its diagonal 0-7 (corner bits: x = 1, y = 2, z = 4).
  static constexpr std::array<std::array<int, 4>, 6> kTetrahedra = {
      {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}}};
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        std::array<int64_t, 8> corner;
        int inside_corners = 0;
        for (int c = 0; c < 8; ++c) {
          corner[size_t(c)] = node(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          inside_corners += value[size_t(corner[size_t(c)])] > 0;
        }
        if (inside_corners == 0 || inside_corners == 8) continue;
        for (const auto& tet : kTetrahedra) {
          std::vector<int64_t> in, out;
          for (int c : tet) (value[size_t(corner[size_t(c)])] > 0 ? in : out).push_back(corner[size_t(c)]);
          if (in.empty() || out.empty()) continue;
          Eigen::Vector3d in_centre = Eigen::Vector3d::Zero(), out_centre = Eigen::Vector3d::Zero();
          for (int64_t p : in) in_centre += position(p) / double(in.size());
          for (int64_t p : out) out_centre += position(p) / double(out.size());
          const Eigen::Vector3d outward = out_centre - in_centre;
          if (in.size() == 1) {
            add_face(edge_vertex(in[0], out[0]), edge_vertex(in[0], out[1]), edge_vertex(in[0], out[2]), outward);
          } else if (out.size() == 1) {
            add_face(edge_vertex(in[0], out[0]), edge_vertex(in[1], out[0]), edge_vertex(in[2], out[0]), outward);
          } else {  // two in, two out: the quad in0-out0, in0-out1, in1-out1, in1-out0
            const int a = edge_vertex(in[0], out[0]), b = edge_vertex(in[0], out[1]);
            const int c = edge_vertex(in[1], out[1]), d = edge_vertex(in[1], out[0]);
            add_face(a, b, c, outward);
            add_face(a, c, d, outward);
          }
        }
      }
  TriangleMesh mesh;
  mesh.vertices.resize(Eigen::Index(vertices.size()), 3);
  for (size_t v = 0; v < vertices.size(); ++v) mesh.vertices.row(Eigen::Index(v)) = vertices[v].transpose();
  mesh.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) mesh.faces.row(Eigen::Index(f)) = faces[f].transpose();
  return mesh;
}

inline TriangleMesh sphere_surface(double radius, double spacing = 1.0) {
  return implicit_surface([radius](const Eigen::Vector3d& p) { return radius - p.norm(); }, radius + 3, spacing);
}

// An ellipsoid (semi-axes 30, 20, 15 mm) with a knob (radius 8 mm) on one side: no symmetry,
// so a rigid registration has one answer.
inline TriangleMesh knobbly_ellipsoid(double spacing = 1.0) {
  return implicit_surface(
      [](const Eigen::Vector3d& p) {
        const double ellipsoid = 15.0 * (1.0 - p.cwiseQuotient(Eigen::Vector3d(30, 20, 15)).norm());
        const double knob = 8.0 - (p - Eigen::Vector3d(20, 10, 8)).norm();
        return std::max(ellipsoid, knob);
      },
      34, spacing);
}

}  // namespace maxillo::validation::test
