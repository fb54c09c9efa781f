// Plane sections with known answers: a sphere cut off-centre gives one closed circle of the right
// radius, a cube gives its square, an open patch gives an open line, and a miss gives nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "geometry/mesh_transform.h"
#include "mesh/plane_section.h"
#include "mesh/surface_extraction.h"

namespace maxillo {
namespace {

// A sphere of radius r about `centre`: iso-surface of a fine volume, vertices on the sphere to a few hundredths of a mm.
TriangleMesh sphere(double radius, const Eigen::Vector3d& centre) {
  Volume v;
  const double spacing = 0.5;
  const int n = int(std::ceil(2 * (radius + 2) / spacing));
  v.geometry.size = Eigen::Vector3i::Constant(n);
  v.geometry.spacing = Eigen::Vector3d::Constant(spacing);
  v.geometry.origin = centre - Eigen::Vector3d::Constant((n - 1) * spacing / 2);
  v.hu.resize(size_t(v.geometry.voxel_count()));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        v.hu[size_t(v.geometry.index(i, j, k))] =
            int16_t(std::lround(100.0 * (radius - (v.geometry.world(Eigen::Vector3d(i, j, k)) - centre).norm())));
  SurfaceOptions options;
  options.smoothing_iterations = 0;
  return extract_surface(v, 0, options);
}

// The unit cube [0, 1]^3 in 12 triangles, counter-clockwise from outside.
TriangleMesh unit_cube() {
  TriangleMesh cube;
  cube.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i) cube.vertices.row(i) << (i & 1), (i >> 1) & 1, (i >> 2) & 1;
  cube.faces.resize(12, 3);
  cube.faces << 0, 2, 1, 1, 2, 3,  // z = 0, normal -z
      4, 5, 6, 5, 7, 6,            // z = 1
      0, 1, 4, 1, 5, 4,            // y = 0
      2, 6, 3, 3, 6, 7,            // y = 1
      0, 4, 2, 2, 4, 6,            // x = 0
      1, 3, 5, 3, 7, 5;            // x = 1
  return cube;
}

double length(const std::vector<Eigen::Vector3d>& line) {
  double sum = 0;
  for (size_t i = 1; i < line.size(); ++i) sum += (line[i] - line[i - 1]).norm();
  return sum;
}

// Twice the signed area of a loop's projection on the xy plane (positive: counter-clockwise seen from +z).
double signed_area_xy(const std::vector<Eigen::Vector3d>& loop) {
  double sum = 0;
  for (size_t i = 1; i < loop.size(); ++i) sum += loop[i - 1].x() * loop[i].y() - loop[i].x() * loop[i - 1].y();
  return sum / 2;
}

TEST(PlaneSection, SphereCutOffCentreIsOneCircleOfTheRightRadius) {
  const Eigen::Vector3d centre(10, -5, 3);
  const double radius = 20, height = 12;  // plane z = centre.z + 12: circle radius 16
  const auto lines =
      plane_section(sphere(radius, centre), centre + Eigen::Vector3d(0, 0, height), Eigen::Vector3d(0, 0, 2));
  ASSERT_EQ(lines.size(), 1u);
  const auto& loop = lines[0];
  ASSERT_GT(loop.size(), 50u);
  EXPECT_EQ(loop.front(), loop.back());  // closed
  const double circle_radius = std::sqrt(radius * radius - height * height);
  for (const auto& p : loop) {
    EXPECT_NEAR(p.z(), centre.z() + height, 1e-9);
    EXPECT_NEAR((p - centre).head<2>().norm(), circle_radius, 0.05);
  }
  EXPECT_NEAR(length(loop), 2 * M_PI * circle_radius, 0.01 * 2 * M_PI * circle_radius);
  EXPECT_NEAR(signed_area_xy(loop) - 0, M_PI * circle_radius * circle_radius,
              0.02 * M_PI * circle_radius * circle_radius)
      << "counter-clockwise seen from +z";
}

TEST(PlaneSection, CubeCutsAreItsSquareWhateverTheTriangulation) {
  const TriangleMesh cube = unit_cube();
  const auto lines = plane_section(cube, {0.3, 0.3, 0.3}, {0, 0, 1});
  ASSERT_EQ(lines.size(), 1u);
  const auto& loop = lines[0];
  EXPECT_EQ(loop.front(), loop.back());
  EXPECT_NEAR(length(loop), 4.0, 1e-12);
  EXPECT_NEAR(signed_area_xy(loop), 1.0, 1e-12);
  for (const auto& p : loop) {
    EXPECT_NEAR(p.z(), 0.3, 1e-12);
    const bool on_side = std::abs(p.x()) < 1e-12 || std::abs(p.x() - 1) < 1e-12 || std::abs(p.y()) < 1e-12 ||
                         std::abs(p.y() - 1) < 1e-12;
    EXPECT_TRUE(on_side) << p.transpose();
  }
  // A plane through the cube's vertices (a diagonal cut x = y): the diagonal rectangle, sides 1 and sqrt 2.
  const auto diagonal = plane_section(cube, {0, 0, 0}, {1, -1, 0});
  ASSERT_EQ(diagonal.size(), 1u);
  EXPECT_NEAR(length(diagonal[0]), 2 + 2 * std::sqrt(2.0), 1e-12);
  for (size_t i = 1; i < diagonal[0].size(); ++i) EXPECT_GT((diagonal[0][i] - diagonal[0][i - 1]).norm(), 1e-9);
}

TEST(PlaneSection, AnOpenSurfaceGivesAnOpenLineAndAMissGivesNothing) {
  TriangleMesh cube = unit_cube();
  cube.faces.conservativeResize(10, 3);  // without the x = 1 side: open there
  const auto lines = plane_section(cube, {0.5, 0.5, 0.5}, {0, 0, 1});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].front(), lines[0].back());
  EXPECT_NEAR(length(lines[0]), 3.0, 1e-12);
  EXPECT_TRUE(plane_section(unit_cube(), {0, 0, 5}, {0, 0, 1}).empty());
  EXPECT_THROW(plane_section(unit_cube(), {0, 0, 0}, {0, 0, 0}), Error);
}

}  // namespace
}  // namespace maxillo
