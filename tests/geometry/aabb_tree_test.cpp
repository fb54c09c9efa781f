// The hierarchy must give exactly the brute-force answers: every triangle pair tested.
#include "geometry/aabb_tree.h"

#include <gtest/gtest.h>

#include "support/test_meshes.h"

namespace maxillo {
namespace {

using testing::random_pose;
using testing::random_soup;

Triangle placed(const AabbTree& tree, int face, const Eigen::Isometry3d& pose) {
  const Triangle t = tree.triangle(face);
  return {pose * t.a, pose * t.b, pose * t.c};
}

std::vector<FacePair> brute_force_pairs(const AabbTree& a, const AabbTree& b, const Eigen::Isometry3d& b_to_a) {
  std::vector<FacePair> pairs;
  for (int i = 0; i < int(a.mesh().face_count()); ++i)
    for (int j = 0; j < int(b.mesh().face_count()); ++j)
      if (triangles_intersect(a.triangle(i), placed(b, j, b_to_a))) pairs.emplace_back(i, j);
  return pairs;
}

TEST(AabbTree, IntersectingFacesEqualBruteForceOverManySeeds) {
  size_t total = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const TriangleMesh a = random_soup(seed, 80, 10, 1.5);
    const TriangleMesh b = random_soup(seed + 1000, 70, 10, 1.5);
    AabbTree ta(a), tb(b);
    std::mt19937 rng(seed);
    const Eigen::Isometry3d pose = random_pose(rng, 2.0, 0.5);
    const auto expected = brute_force_pairs(ta, tb, pose);
    ASSERT_EQ(ta.intersecting_faces(tb, pose), expected) << "seed " << seed;
    total += expected.size();
  }
  EXPECT_GT(total, 200u);  // the comparison saw plenty of collisions
}

TEST(AabbTree, TouchingCopiesCollideEverywhere) {
  const TriangleMesh a = random_soup(3, 50, 10, 1.0);
  AabbTree ta(a), tb(a);
  // Each triangle meets itself; at identity every diagonal pair must be present.
  const auto pairs = ta.intersecting_faces(tb, Eigen::Isometry3d::Identity());
  for (int f = 0; f < 50; ++f) EXPECT_TRUE(std::binary_search(pairs.begin(), pairs.end(), FacePair{f, f}));
}

TEST(AabbTree, NearestEqualsBruteForce) {
  for (unsigned seed = 1; seed <= 50; ++seed) {
    const TriangleMesh mesh = random_soup(seed, 120, 10, 1.5);
    AabbTree tree(mesh);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> where(-2, 12);
    for (int n = 0; n < 40; ++n) {
      const Eigen::Vector3d p(where(rng), where(rng), where(rng));
      double best = 1e300;
      for (int f = 0; f < int(mesh.face_count()); ++f)
        best = std::min(best, (closest_point_on_triangle(p, tree.triangle(f)).point - p).norm());
      const NearestPoint found = tree.nearest(p, 1e9);
      ASSERT_GE(found.face, 0);
      ASSERT_NEAR(found.distance, best, 1e-12) << "seed " << seed;
      ASSERT_NEAR((found.point - p).norm(), best, 1e-12);
      // A radius below the true distance finds nothing; one above finds the same distance.
      EXPECT_LT(tree.nearest(p, 0.999 * best).face, 0);
      EXPECT_NEAR(tree.nearest(p, 1.001 * best + 1e-9).distance, best, 1e-12);
    }
  }
}

TEST(AabbTree, FacesNearContainEveryFaceWithinTheGap) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const TriangleMesh a = random_soup(seed, 60, 10, 1.0), b = random_soup(seed + 77, 60, 10, 1.0);
    AabbTree ta(a), tb(b);
    std::mt19937 rng(seed);
    const Eigen::Isometry3d pose = random_pose(rng, 1.0, 0.3);
    const double gap = 0.5;
    const auto [near_a, near_b] = ta.faces_near(tb, pose, gap);
    // Brute force: a vertex of face i within `gap` of triangle j makes both faces near.
    for (int i = 0; i < 60; ++i)
      for (int j = 0; j < 60; ++j) {
        const Triangle ti = ta.triangle(i), tj = placed(tb, j, pose);
        double d = 1e300;
        for (const auto* v : {&ti.a, &ti.b, &ti.c})
          d = std::min(d, (closest_point_on_triangle(*v, tj).point - *v).norm());
        if (d <= gap) {
          ASSERT_TRUE(near_a[size_t(i)]) << "seed " << seed;
          ASSERT_TRUE(near_b[size_t(j)]) << "seed " << seed;
        }
      }
  }
}

}  // namespace
}  // namespace maxillo
