#include <gtest/gtest.h>

#include <cmath>

#include "geometry/mesh_measures.h"
#include "geometry/mesh_transform.h"

namespace maxillo {
namespace {

// Volume of a prism over a regular n-gon inscribed in a circle of radius r, height h.
double prism_volume(int n, double r, double h) { return 0.5 * n * r * r * std::sin(2 * M_PI / n) * h; }

TEST(CylinderMesh, IsClosedOutwardAndHasThePrismVolume) {
  const Eigen::Vector3d a(1, 2, 3), b(4, -2, 15);
  auto mesh = cylinder_mesh(a, b, 2.0, 16);
  EXPECT_TRUE(is_watertight(mesh));
  EXPECT_NEAR(signed_volume(mesh), prism_volume(16, 2.0, (b - a).norm()), 1e-9);
}

TEST(Transformed, KeepsVolumeAndMovesPointsRigidly) {
  auto mesh = cylinder_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 10), 3.0);
  Eigen::Isometry3d move =
      Eigen::Translation3d(5, -7, 2) * Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized());
  auto moved = transformed(mesh, move);
  EXPECT_NEAR(signed_volume(moved), signed_volume(mesh), 1e-9);
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
    EXPECT_LT((moved.vertices.row(v).transpose() - move * Eigen::Vector3d(mesh.vertices.row(v).transpose())).norm(),
              1e-12);
}

TEST(Merged, AddsVolumesAndKeepsEachPartClosed) {
  auto one = cylinder_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 10), 1.0);
  auto two = cylinder_mesh(Eigen::Vector3d(20, 0, 0), Eigen::Vector3d(20, 0, 5), 2.0);
  auto both = merged({&one, &two});
  EXPECT_EQ(both.face_count(), one.face_count() + two.face_count());
  EXPECT_TRUE(is_watertight(both));
  EXPECT_NEAR(signed_volume(both), signed_volume(one) + signed_volume(two), 1e-9);
  EXPECT_EQ(connected_components(both).face_counts.size(), 2u);
}

}  // namespace
}  // namespace maxillo
