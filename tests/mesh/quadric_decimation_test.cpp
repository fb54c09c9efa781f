// decimate_quadric on shapes with known answers: a finely cut box keeps its exact planes and
// volume, a sphere stays on its radius, a torus keeps its hole, an open sheet keeps its border,
// and the same mesh gives the same bits.
#include "mesh/quadric_decimation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "geometry/mesh_measures.h"
#include "support/test_shapes.h"

namespace maxillo {
namespace {

// Vertices on a (rows + 1) x (cols + 1) grid of (u, v) in [0, 1]^2, two triangles per cell;
// `wrap_u` / `wrap_v` join the last column / row to the first (a closed tube or torus).
template <typename Surface>
TriangleMesh parametric_mesh(int rows, int cols, bool wrap_u, bool wrap_v, Surface point) {
  const int nu = wrap_u ? cols : cols + 1, nv = wrap_v ? rows : rows + 1;
  TriangleMesh m;
  m.vertices.resize(nu * nv, 3);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) m.vertices.row(j * nu + i) = point(double(i) / cols, double(j) / rows).transpose();
  m.faces.resize(2 * rows * cols, 3);
  int f = 0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const int a = j * nu + i, b = j * nu + (i + 1) % nu, c = ((j + 1) % nv) * nu + i,
                d = ((j + 1) % nv) * nu + (i + 1) % nu;
      m.faces.row(f++) << a, b, d;
      m.faces.row(f++) << a, d, c;
    }
  return m;
}

TriangleMesh torus(double major, double minor, int rows, int cols) {
  return parametric_mesh(rows, cols, true, true, [&](double u, double v) {
    const double a = 2 * std::numbers::pi * u, b = 2 * std::numbers::pi * v;
    return Eigen::Vector3d((major + minor * std::cos(b)) * std::cos(a), (major + minor * std::cos(b)) * std::sin(a),
                           minor * std::sin(b));
  });
}

// A closed box [0, 2] x [0, 3] x [0, 4] whose every face is cut into n x n squares.
TriangleMesh fine_box(int n) {
  TriangleMesh box = testing::cube(1);
  for (int level = 0; level < n; ++level) {  // midpoint subdivision, level times
    std::map<std::pair<int, int>, int> middle;
    std::vector<Eigen::Vector3d> points;
    for (Eigen::Index v = 0; v < box.vertex_count(); ++v) points.push_back(box.vertices.row(v).transpose());
    auto mid = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto [it, added] = middle.try_emplace(key, int(points.size()));
      if (added) points.push_back(0.5 * (points[size_t(a)] + points[size_t(b)]));
      return it->second;
    };
    FaceMatrix faces(box.face_count() * 4, 3);
    for (Eigen::Index f = 0; f < box.face_count(); ++f) {
      const int a = box.faces(f, 0), b = box.faces(f, 1), c = box.faces(f, 2);
      const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      faces.row(4 * f) << a, ab, ca;
      faces.row(4 * f + 1) << ab, b, bc;
      faces.row(4 * f + 2) << ca, bc, c;
      faces.row(4 * f + 3) << ab, bc, ca;
    }
    box.faces = faces;
    box.vertices.resize(Eigen::Index(points.size()), 3);
    for (size_t v = 0; v < points.size(); ++v) box.vertices.row(Eigen::Index(v)) = points[v].transpose();
  }
  for (Eigen::Index v = 0; v < box.vertex_count(); ++v)
    box.vertices.row(v).array() *= Eigen::RowVector3d(2, 3, 4).array();
  return box;
}

int euler_characteristic(const TriangleMesh& m) {
  return int(m.vertex_count()) - int(3 * m.face_count() / 2) + int(m.face_count());
}

TEST(QuadricDecimation, AFinelyCutBoxKeepsItsPlanesItsVolumeAndItsCorners) {
  const TriangleMesh box = fine_box(5);  // 12 x 4^5 = 12,288 triangles
  const auto result = decimate_quadric(box, {.target_triangles = 200});
  const TriangleMesh& m = result.mesh;
  EXPECT_TRUE(result.reached_target);
  EXPECT_LE(m.face_count(), 200);
  EXPECT_TRUE(is_watertight(m));
  EXPECT_EQ(euler_characteristic(m), 2);
  EXPECT_NEAR(signed_volume(m), 24.0, 1e-9);
  EXPECT_NEAR(surface_area(m), 2 * (6 + 8 + 12), 1e-9);
  for (Eigen::Index v = 0; v < m.vertex_count(); ++v) {  // every vertex still on a face of the box
    const Eigen::Array3d p = m.vertices.row(v).transpose().array(), size(2, 3, 4);
    const double off_planes = std::min(p.abs().minCoeff(), (p - size).abs().minCoeff());
    EXPECT_LT(off_planes, 1e-9) << "vertex " << v;
  }
}

TEST(QuadricDecimation, ASphereStaysOnItsRadius) {
  const double radius = 10;
  const TriangleMesh sphere = parametric_mesh(120, 240, true, false, [&](double u, double v) {
    const double theta = std::numbers::pi * (0.02 + 0.96 * v),
                 phi = 2 * std::numbers::pi * u;  // poles left open: a tube
    return Eigen::Vector3d(radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                           radius * std::cos(theta));
  });
  const auto result = decimate_quadric(sphere, {.target_triangles = 5000});
  EXPECT_LE(result.mesh.face_count(), 5000);
  double largest_off = 0;
  for (Eigen::Index v = 0; v < result.mesh.vertex_count(); ++v)
    largest_off = std::max(largest_off, std::abs(result.mesh.vertices.row(v).norm() - radius));
  // 5,000 triangles over 1,250 mm^2: edges of ~1.6 mm, whose chords sag 0.03 mm below a 10 mm sphere.
  EXPECT_LT(largest_off, 0.05);
}

TEST(QuadricDecimation, AnOpenSheetKeepsItsBorderInPlace) {
  const TriangleMesh sheet = parametric_mesh(60, 60, false, false, [](double u, double v) {
    return Eigen::Vector3d(10 * u, 10 * v, std::sin(3 * u) * std::cos(2 * v));
  });
  const auto before = count_edges(sheet);
  const auto result = decimate_quadric(sheet, {.target_triangles = 1000});
  const auto after = count_edges(result.mesh);
  EXPECT_EQ(after.boundary, before.boundary) << "border vertices are never merged";
  EXPECT_EQ(after.non_manifold, 0);
  EXPECT_EQ(after.inconsistent, 0);
  EXPECT_LE(result.mesh.face_count(), 1000);
}

TEST(QuadricDecimation, ATorusKeepsItsHoleAndItsSize) {
  const TriangleMesh ring = torus(20, 6, 100, 300);
  const auto result = decimate_quadric(ring, {.target_triangles = 3000});
  EXPECT_TRUE(is_watertight(result.mesh));
  EXPECT_EQ(euler_characteristic(result.mesh), 0) << "genus 1";
  EXPECT_EQ(connected_components(result.mesh).face_counts.size(), 1u);
  EXPECT_NEAR(signed_volume(result.mesh) / signed_volume(ring), 1.0, 0.01);
}

TEST(QuadricDecimation, TheSameMeshGivesTheSameBits) {
  const TriangleMesh ring = torus(20, 6, 80, 200);
  const auto first = decimate_quadric(ring, {.target_triangles = 2000});
  const auto second = decimate_quadric(ring, {.target_triangles = 2000});
  EXPECT_EQ(first.mesh.vertices, second.mesh.vertices);
  EXPECT_EQ(first.mesh.faces, second.mesh.faces);
}

TEST(QuadricDecimation, AMeshAlreadyWithinTheTargetIsReturnedAsItIs) {
  const TriangleMesh cube = testing::cube(2);
  const auto result = decimate_quadric(cube, {.target_triangles = 12});
  EXPECT_EQ(result.collapses, 0);
  EXPECT_EQ(result.mesh.vertices, cube.vertices);
  EXPECT_EQ(result.mesh.faces, cube.faces);
}

TEST(QuadricDecimation, NeverGoesBelowATetrahedron) {
  const auto result = decimate_quadric(fine_box(2), {.target_triangles = 1});
  EXPECT_FALSE(result.reached_target);
  EXPECT_GE(result.mesh.face_count(), 4);
  EXPECT_TRUE(is_watertight(result.mesh));
}

}  // namespace
}  // namespace maxillo
