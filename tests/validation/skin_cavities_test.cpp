// Cavity linings on a sphere with a slit cut into it (a closed mouth, schematically): the slit's
// walls face each other across 2 mm and line a cavity; the rest of the sphere faces open air.
#include <gtest/gtest.h>

#include <algorithm>

#include "test_surfaces.h"
#include "validation/skin_cavities.h"

namespace maxillo::validation {
namespace {

// Sphere of radius 12 mm with a slit 2 mm wide (|z| < 1) reaching from x = 12 in to x = 3: a lip's
// size, and small enough that the sanitizer build (Eigen not inlined at -O1) runs it in seconds.
TriangleMesh slit_sphere() {
  return test::implicit_surface(
      [](const Eigen::Vector3d& p) {
        const double in_sphere = 12 - p.norm();
        const double out_of_slit = std::max(std::abs(p.z()) - 1.0, 3.0 - p.x());
        return std::min(in_sphere, out_of_slit);  // the sphere without the slit
      },
      14, 0.5);
}

TEST(SkinCavities, SlitWallsLineACavityAndTheOuterSphereDoesNot) {
  const TriangleMesh mesh = slit_sphere();
  const auto cavity = cavity_vertices(mesh);
  int walls = 0, walls_found = 0, outer = 0, outer_found = 0;
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector3d p = mesh.vertices.row(v).transpose();
    if (std::abs(std::abs(p.z()) - 1) < 0.3 && p.x() > 5 && p.norm() < 10.5) {  // deep in the slit, on a wall
      ++walls;
      walls_found += cavity[size_t(v)];
    } else if (p.norm() > 11.5 && p.x() < 0) {  // the far side of the sphere
      ++outer;
      outer_found += cavity[size_t(v)];
    }
  }
  ASSERT_GT(walls, 50);
  ASSERT_GT(outer, 500);
  EXPECT_GT(walls_found, 0.95 * walls);
  EXPECT_EQ(outer_found, 0);
}

TEST(SkinCavities, OnlyIncludedVerticesAreTested) {
  const TriangleMesh mesh = slit_sphere();
  const auto cavity = cavity_vertices(mesh, std::vector<bool>(size_t(mesh.vertex_count()), false));
  EXPECT_EQ(std::count(cavity.begin(), cavity.end(), true), 0);
}

}  // namespace
}  // namespace maxillo::validation
