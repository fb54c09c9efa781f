#include "geometry/plane_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

namespace maxillo {
namespace {

TEST(FitPlane, PointsOnAPlaneGiveThatPlane) {
  const Eigen::Vector3d normal = Eigen::Vector3d(1, 2, -2).normalized();
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  const Eigen::Vector3d origin(4, -3, 9);
  std::vector<Eigen::Vector3d> points;
  for (int i = -3; i <= 3; ++i)
    for (int j = -2; j <= 2; ++j) points.push_back(origin + 7.0 * i * u + 5.0 * j * v);
  const auto plane = fit_plane(points);
  ASSERT_TRUE(plane);
  EXPECT_LT((plane->centroid - origin).norm(), 1e-12);  // the grid is symmetric about origin
  EXPECT_NEAR(std::abs(plane->normal.dot(normal)), 1, 1e-12);
}

TEST(FitPlane, SymmetricOffsetsAverageOut) {
  // Points alternately 1 mm above and below z = 2: the least-squares plane is z = 2.
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) points.emplace_back(i * 3.0, j * 3.0, 2 + ((i + j) % 2 ? 1 : -1));
  const auto plane = fit_plane(points);
  ASSERT_TRUE(plane);
  EXPECT_NEAR(plane->centroid.z(), 2, 1e-12);
  EXPECT_NEAR(std::abs(plane->normal.z()), 1, 1e-3);
}

TEST(FitPlane, TooFewOrCollinearPointsHaveNoPlane) {
  EXPECT_FALSE(fit_plane(std::vector<Eigen::Vector3d>{{0, 0, 0}, {1, 1, 1}}));
  EXPECT_FALSE(fit_plane(std::vector<Eigen::Vector3d>{{0, 0, 0}, {10, 10, 10}, {20, 20, 20}, {35, 35, 35}}));
  EXPECT_TRUE(fit_plane(std::vector<Eigen::Vector3d>{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}}));
}

}  // namespace
}  // namespace maxillo
