#include "geometry/anatomical_frame.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace maxillo {
namespace {

// Porions and orbitales of an average adult head in a frame where anterior = -y,
// superior = +z, left = +x (mm).
FrankfortPoints canonical_points() {
  return {.porion_right = Eigen::Vector3d(-60, 10, 0),
          .porion_left = Eigen::Vector3d(60, 10, 0),
          .orbitale_right = Eigen::Vector3d(-33, -70, 0),
          .orbitale_left = Eigen::Vector3d(33, -70, 0)};
}

FrankfortPoints moved(FrankfortPoints points, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift) {
  for (auto* p : {&points.porion_right, &points.porion_left, &points.orbitale_right, &points.orbitale_left})
    if (*p) **p = rotation * **p + shift;
  return points;
}

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_LT((actual - expected).norm(), tolerance)
      << "actual " << actual.transpose() << " expected " << expected.transpose();
}

TEST(AnatomicalFrame, WithoutPointsUsesPatientAxes) {
  const AnatomicalFrame frame = frankfort_frame({});
  EXPECT_EQ(frame.source, FrameSource::PatientAxes);
  expect_near(frame.anterior, {0, -1, 0}, 1e-12);
  expect_near(frame.superior, {0, 0, 1}, 1e-12);
  expect_near(frame.left, {1, 0, 0}, 1e-12);
  expect_near(frame.origin, {0, 0, 0}, 1e-12);
}

TEST(AnatomicalFrame, FrankfortFrameFollowsARotatedHead) {
  // Head pitched 20 degrees chin-down and turned 30 degrees, then moved.
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(0.52, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  const Eigen::Vector3d shift(12, -150, 300);
  const AnatomicalFrame frame = frankfort_frame(moved(canonical_points(), rotation, shift));
  EXPECT_EQ(frame.source, FrameSource::Frankfort);
  expect_near(frame.anterior, rotation * Eigen::Vector3d(0, -1, 0), 1e-9);
  expect_near(frame.superior, rotation * Eigen::Vector3d(0, 0, 1), 1e-9);
  expect_near(frame.left, rotation * Eigen::Vector3d(1, 0, 0), 1e-9);
  expect_near(frame.origin, rotation * Eigen::Vector3d(0, 10, 0) + shift, 1e-9);
  EXPECT_NEAR(frame.anterior.cross(frame.left).dot(frame.superior), 1.0, 1e-12);  // right-handed
}

TEST(AnatomicalFrame, OneOrbitaleIsEnoughAndFrameStaysOrthonormal) {
  const AnatomicalFrame frame = frankfort_frame({.porion_right = Eigen::Vector3d(-60, 10, 3),
                                                 .porion_left = Eigen::Vector3d(60, 12, -2),
                                                 .orbitale_left = Eigen::Vector3d(33, -70, 1)});
  ASSERT_EQ(frame.source, FrameSource::Frankfort);
  EXPECT_NEAR(frame.anterior.norm(), 1, 1e-12);
  EXPECT_NEAR(frame.anterior.dot(frame.left), 0, 1e-12);
  EXPECT_NEAR(frame.superior.dot(frame.left), 0, 1e-12);
  EXPECT_GT(frame.anterior.dot(Eigen::Vector3d(0, -1, 0)), 0.99);
}

TEST(AnatomicalFrame, DegeneratePointsFallBack) {
  // Porions 5 mm apart: no reliable transverse axis.
  EXPECT_EQ(frankfort_frame({.porion_right = Eigen::Vector3d(-2, 0, 0),
                             .porion_left = Eigen::Vector3d(3, 0, 0),
                             .orbitale_right = Eigen::Vector3d(0, -70, 0)})
                .source,
            FrameSource::PatientAxes);
  // Orbitale on the porion axis: no forward direction.
  EXPECT_EQ(frankfort_frame({.porion_right = Eigen::Vector3d(-60, 0, 0),
                             .porion_left = Eigen::Vector3d(60, 0, 0),
                             .orbitale_right = Eigen::Vector3d(30, 0, 0)})
                .source,
            FrameSource::PatientAxes);
  // Missing orbitales.
  EXPECT_EQ(
      frankfort_frame({.porion_right = Eigen::Vector3d(-60, 0, 0), .porion_left = Eigen::Vector3d(60, 0, 0)}).source,
      FrameSource::PatientAxes);
}

}  // namespace
}  // namespace maxillo
