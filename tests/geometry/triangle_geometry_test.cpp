#include "geometry/triangle_geometry.h"

#include <gtest/gtest.h>

#include <random>

namespace maxillo {
namespace {

using Eigen::Vector3d;

// Independent reference for triangles in general position: they intersect iff an edge of one
// crosses the other (segment-triangle test, Moeller-Trumbore).
bool segment_hits_triangle(const Vector3d& p0, const Vector3d& p1, const Triangle& t) {
  const Vector3d d = p1 - p0, e1 = t.b - t.a, e2 = t.c - t.a;
  const Vector3d h = d.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-15) return false;
  const Vector3d s = p0 - t.a;
  const double u = s.dot(h) / det;
  const Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det, w = e2.dot(q) / det;
  return u >= 0 && v >= 0 && u + v <= 1 && w >= 0 && w <= 1;
}

bool reference_intersect(const Triangle& p, const Triangle& q) {
  return segment_hits_triangle(p.a, p.b, q) || segment_hits_triangle(p.b, p.c, q) ||
         segment_hits_triangle(p.c, p.a, q) || segment_hits_triangle(q.a, q.b, p) ||
         segment_hits_triangle(q.b, q.c, p) || segment_hits_triangle(q.c, q.a, p);
}

TEST(TrianglesIntersect, AgreesWithEdgeCrossingReferenceOnRandomTriangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int hits = 0;
  for (int n = 0; n < 20000; ++n) {
    Triangle p{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    Triangle q{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    const bool expected = reference_intersect(p, q);
    ASSERT_EQ(triangles_intersect(p, q), expected) << "case " << n;
    ASSERT_EQ(triangles_intersect(q, p), expected) << "case " << n;
    hits += expected;
  }
  EXPECT_GT(hits, 2000);  // both outcomes well represented
  EXPECT_LT(hits, 18000);
}

TEST(TrianglesIntersect, CoplanarCases) {
  const Triangle base{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  EXPECT_TRUE(triangles_intersect(base, {{1, 1, 0}, {2, 1, 0}, {1, 2, 0}}));         // contained
  EXPECT_TRUE(triangles_intersect(base, {{3, 3, 0}, {-1, 1, 0}, {1, -1, 0}}));       // overlapping
  EXPECT_TRUE(triangles_intersect(base, {{2, 2, 0}, {5, 5, 0}, {2, 5, 0}}));         // touching at a point
  EXPECT_FALSE(triangles_intersect(base, {{2.1, 2.1, 0}, {5, 5, 0}, {2.1, 5, 0}}));  // just apart
  EXPECT_FALSE(triangles_intersect(base, {{5, 0, 0}, {6, 0, 0}, {5, 1, 0}}));
}

TEST(TrianglesIntersect, TouchingAndParallelCases) {
  const Triangle base{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  EXPECT_TRUE(triangles_intersect(base, {{1, 1, 0}, {1, 1, 3}, {2, 1, 3}}));      // vertex on the face
  EXPECT_FALSE(triangles_intersect(base, {{1, 1, 0.01}, {1, 1, 3}, {2, 1, 3}}));  // just above
  EXPECT_FALSE(triangles_intersect(base, {{0, 0, 1}, {4, 0, 1}, {0, 4, 1}}));     // parallel planes
  EXPECT_TRUE(triangles_intersect(base, {{2, -1, 0}, {2, 5, 0}, {2, 0, 3}}));     // edge lies in the plane
  EXPECT_TRUE(triangles_intersect(base, {{1, 1, -1}, {1, 1, 1}, {1, 1, 2}}));     // needle through the face
  EXPECT_FALSE(triangles_intersect(base, {{5, 5, -1}, {5, 5, 1}, {5, 5, 2}}));    // needle beside it
  EXPECT_TRUE(triangles_intersect(base, {{1, 1, 0}, {1, 1, 0}, {1, 1, 0}}));      // point on the face
}

TEST(ClosestPointOnTriangle, NeverFartherThanAnySampleAndMatchesDenseSampling) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int n = 0; n < 300; ++n) {
    const Triangle t{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    const Vector3d p(u(rng), u(rng), u(rng));
    const double exact = (closest_point_on_triangle(p, t).point - p).norm();
    double sampled = 1e300;
    constexpr int kSteps = 200;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j) {
        const double a = double(i) / kSteps, b = double(j) / kSteps;
        sampled = std::min(sampled, (t.a + a * (t.b - t.a) + b * (t.c - t.a) - p).norm());
      }
    ASSERT_LE(exact, sampled + 1e-12);
    ASSERT_NEAR(exact, sampled, 0.05);
  }
}

TEST(ClosestPointOnTriangle, ReportsTheFeature) {
  const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(closest_point_on_triangle({0.2, 0.2, 1}, t).feature, TriangleFeature::Face);
  EXPECT_EQ(closest_point_on_triangle({-1, -1, 0}, t).feature, TriangleFeature::VertexA);
  EXPECT_EQ(closest_point_on_triangle({0.5, -1, 0}, t).feature, TriangleFeature::EdgeAB);
  EXPECT_EQ(closest_point_on_triangle({1, 1, 0}, t).feature, TriangleFeature::EdgeBC);
  EXPECT_TRUE(closest_point_on_triangle({1, 1, 0}, t).point.isApprox(Vector3d(0.5, 0.5, 0)));
  // Zero-area triangle: the nearest point of its segment.
  const Triangle needle{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_NEAR((closest_point_on_triangle({1.5, 1, 0}, needle).point - Vector3d(1.5, 0, 0)).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace maxillo
