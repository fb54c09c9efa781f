// Distance statistics with known answers: a sphere inside a sphere, and samples whose
// statistics are computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "test_surfaces.h"
#include "validation/distance_statistics.h"

namespace maxillo::validation {
namespace {

TEST(DistanceStatistics, HandComputedSample) {
  const std::vector<double> d{-3, -1, 0, 1, 2, 5};
  auto s = distance_statistics(d, 2.0);
  EXPECT_EQ(s.count, 6);
  EXPECT_NEAR(s.mean_absolute, 12.0 / 6, 1e-12);
  EXPECT_NEAR(s.mean_signed, 4.0 / 6, 1e-12);
  EXPECT_NEAR(s.standard_deviation,
              std::sqrt((3.0 + 2 / 3.0) * (3.0 + 2 / 3.0) + (5 / 3.0) * (5 / 3.0) + (2 / 3.0) * (2 / 3.0) +
                        (1 / 3.0) * (1 / 3.0) + (4 / 3.0) * (4 / 3.0) + (13 / 3.0) * (13 / 3.0)) /
                  std::sqrt(5.0),
              1e-12);
  EXPECT_NEAR(s.p50, 0.5, 1e-12);    // between 0 and 1
  EXPECT_NEAR(s.p25, -0.75, 1e-12);  // rank 1.25: -1 + 0.25
  EXPECT_NEAR(s.p95, 4.25, 1e-12);   // rank 4.75: 2 + 0.75 * 3
  EXPECT_NEAR(s.max_absolute, 5, 1e-12);
  EXPECT_NEAR(s.within_tolerance_percent, 100.0 * 4 / 6, 1e-12);
}

TEST(DistanceStatistics, EmptySampleIsAllZero) {
  auto s = distance_statistics(std::vector<double>{});
  EXPECT_EQ(s.count, 0);
  EXPECT_EQ(s.p95, 0);
}

// The spheres' vertices lie on them to within h^2 / 8R (0.003 mm at the 1 mm grid), well inside
// the tolerances; a finer grid only made the test slower (four times the triangles).
TEST(SignedSurfaceDistances, SphereInsideASphereIsMinusTheGapEverywhere) {
  const auto inner = test::sphere_surface(38), outer = test::sphere_surface(40);
  auto d = signed_surface_distances(inner, outer);
  ASSERT_EQ(d.size(), size_t(inner.vertex_count()));
  auto s = distance_statistics(d);
  // The prediction (inner) lies 2 mm behind the real surface (outer): negative.
  EXPECT_NEAR(s.mean_signed, -2.0, 0.03);
  EXPECT_NEAR(s.p5, -2.0, 0.05);
  EXPECT_NEAR(s.p95, -2.0, 0.05);
  EXPECT_LT(s.standard_deviation, 0.03);
  // And the other way round the sign flips.
  auto back = distance_statistics(signed_surface_distances(outer, inner));
  EXPECT_NEAR(back.mean_signed, 2.0, 0.03);
}

TEST(SignedSurfaceDistances, OnlyTheIncludedVerticesCount) {
  const auto inner = test::sphere_surface(38), outer = test::sphere_surface(40);
  std::vector<bool> upper(size_t(inner.vertex_count()));
  for (Eigen::Index v = 0; v < inner.vertex_count(); ++v) upper[size_t(v)] = inner.vertices(v, 2) > 0;
  auto d = signed_surface_distances(inner, outer, upper);
  EXPECT_EQ(d.size(), size_t(std::count(upper.begin(), upper.end(), true)));
}

}  // namespace
}  // namespace maxillo::validation
