// Non-rigid coherent point drift with known answers, on a closed sphere (a patch's border would
// pull its points inwards and blur the answer): a smooth 2 mm bump is recovered vertex by vertex,
// and as a synthetic outcome its corresponding-point distances are minus the bump's height; a
// sphere against itself gives zero; a sphere 1.5 mm outside (inside) another gives +1.5 (-1.5) mm.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "test_surfaces.h"
#include "validation/coherent_point_drift.h"
#include "validation/distance_statistics.h"

namespace maxillo::validation {
namespace {

constexpr double kRadius = 30;

// A Gaussian bump of 2 mm height and 8 mm standard deviation (along the surface) at the +z pole.
double bump_height(const Eigen::Vector3d& p) {
  const double arc = kRadius * std::acos(std::clamp(p.normalized().z(), -1.0, 1.0));
  return 2.0 * std::exp(-arc * arc / (2 * 8.0 * 8.0));
}

TriangleMesh bumped(const TriangleMesh& sphere) {
  TriangleMesh out = sphere;
  for (Eigen::Index v = 0; v < out.vertex_count(); ++v) {
    const Eigen::Vector3d p = sphere.vertices.row(v).transpose();
    out.vertices.row(v) = (p + bump_height(p) * p.normalized()).transpose();
  }
  return out;
}

CpdOptions quick() {
  CpdOptions options;
  options.max_points = 1200;
  return options;
}

class SphereCpd : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { sphere_ = new TriangleMesh(test::sphere_surface(kRadius)); }
  static void TearDownTestSuite() { delete sphere_; }
  static const TriangleMesh& sphere() { return *sphere_; }
  static inline TriangleMesh* sphere_ = nullptr;
};

TEST_F(SphereCpd, RecoversASmoothBumpVertexByVertex) {
  const TriangleMesh actual = bumped(sphere());
  CpdOptions options;
  options.max_points = 2000;
  const CpdResult result = nonrigid_cpd(actual.vertices, sphere().vertices, options);
  ASSERT_EQ(result.moved.rows(), sphere().vertex_count());
  double sum = 0, worst = 0, worst_at_peak = 0;
  for (Eigen::Index v = 0; v < sphere().vertex_count(); ++v) {
    const double error = (result.moved.row(v) - actual.vertices.row(v)).norm();
    sum += error;
    worst = std::max(worst, error);
    if (bump_height(sphere().vertices.row(v).transpose()) > 1.9) worst_at_peak = std::max(worst_at_peak, error);
  }
  EXPECT_LT(sum / double(sphere().vertex_count()), 0.25) << "mean, of a 2 mm bump";
  EXPECT_LT(worst, 0.8);
  EXPECT_LT(worst_at_peak, 0.8) << "the peak rose by more than 1.2 of its 2 mm";
  EXPECT_GT(result.iterations, 1);
}

TEST_F(SphereCpd, KnownOutcomeGivesItsKnownDistances) {
  // The prediction (the plain sphere) lies behind the outcome (the bumped one) by the bump's height.
  const TriangleMesh actual = bumped(sphere());
  const auto d = corresponding_point_distances(sphere(), actual, {}, quick());
  ASSERT_EQ(d.size(), size_t(sphere().vertex_count()));
  double sum = 0, worst = 0;
  for (Eigen::Index v = 0; v < sphere().vertex_count(); ++v) {
    const double error = std::abs(d[size_t(v)] + bump_height(sphere().vertices.row(v).transpose()));
    sum += error;
    worst = std::max(worst, error);
  }
  EXPECT_LT(sum / double(sphere().vertex_count()), 0.1);
  EXPECT_LT(worst, 0.3);
  EXPECT_NEAR(distance_statistics(d).p5,
              percentile(
                  [&] {
                    std::vector<double> truth;
                    for (Eigen::Index v = 0; v < sphere().vertex_count(); ++v)
                      truth.push_back(-bump_height(sphere().vertices.row(v).transpose()));
                    return truth;
                  }(),
                  5),
              0.25);
}

TEST_F(SphereCpd, TheSameSurfaceGivesZero) {
  const auto d = corresponding_point_distances(sphere(), sphere(), {}, quick());
  ASSERT_EQ(d.size(), size_t(sphere().vertex_count()));
  const auto s = distance_statistics(d);
  EXPECT_LT(s.mean_absolute, 0.1);
  EXPECT_LT(s.max_absolute, 0.3);
}

TEST_F(SphereCpd, AUniformOffsetGivesItsSizeWithTheRightSign) {
  for (const double offset : {1.5, -1.5}) {
    const TriangleMesh predicted = test::sphere_surface(kRadius + offset);
    const auto d = corresponding_point_distances(predicted, sphere(), {}, quick());
    ASSERT_EQ(d.size(), size_t(predicted.vertex_count()));
    const auto s = distance_statistics(d);
    EXPECT_NEAR(s.mean_signed, offset, 0.1) << "offset " << offset;
    EXPECT_NEAR(s.p5, offset, 0.1) << "offset " << offset;
    EXPECT_NEAR(s.p95, offset, 0.1) << "offset " << offset;
  }
}

TEST_F(SphereCpd, OnlyIncludedVerticesAreMeasured) {
  const TriangleMesh predicted = test::sphere_surface(kRadius + 1.5);
  std::vector<bool> include(size_t(predicted.vertex_count()), false);
  size_t wanted = 0;
  for (Eigen::Index v = 0; v < predicted.vertex_count(); ++v)
    if (predicted.vertices(v, 2) > 10) include[size_t(v)] = true, ++wanted;  // a cap, as a face region
  const auto d = corresponding_point_distances(predicted, sphere(), include, quick());
  ASSERT_EQ(d.size(), wanted);
  EXPECT_NEAR(distance_statistics(d).p50, 1.5, 0.15);
  EXPECT_THROW(corresponding_point_distances(predicted, sphere(), std::vector<bool>(3, true), quick()), Error);
}

TEST(CoherentPointDrift, EmptySetsAndBadOptionsAreRefused) {
  VertexMatrix some(4, 3);
  some << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_THROW(nonrigid_cpd(VertexMatrix{}, some), Error);
  EXPECT_THROW(nonrigid_cpd(some, VertexMatrix{}), Error);
  CpdOptions bad;
  bad.outlier_weight = 1.0;
  EXPECT_THROW(nonrigid_cpd(some, some, bad), Error);
  bad = {};
  bad.beta_mm = 0;
  EXPECT_THROW(nonrigid_cpd(some, some, bad), Error);
}

}  // namespace
}  // namespace maxillo::validation
