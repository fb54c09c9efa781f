// The frame-free reading of a flat chin (landmarking/midline_landmarks.h, chin_from_nasion) on
// profiles whose answers are known: a polyline with a kink for the chin's bulge and one for the
// concavity above it, and the same profile turned in its plane, which must move the points with it.
#include <gtest/gtest.h>

#include <cmath>

#include "landmarking/midline_landmarks.h"

namespace maxillo::landmarking {
namespace {

// Upwards from z = 0 to infradentale at z = 30 (y: posterior positive), every 0.25 mm, between the
// corners (z, y): (0, 0), (10, -2) the bulge, (20, 1) the concavity, (30, -3) infradentale.
Profile kinked_symphysis() {
  const double corner_z[] = {0, 10, 20, 30}, corner_y[] = {0, -2, 1, -3};
  Profile front;
  for (double z = 0; z <= 30.001; z += 0.25) {
    const int piece = std::min(2, int(z / 10));
    const double t = (z - corner_z[piece]) / 10;
    front.push_back({z, corner_y[piece] + t * (corner_y[piece + 1] - corner_y[piece]), 0});
  }
  return front;
}

// A point (z, y) turned by `angle` about the origin in the sagittal plane.
ProfilePoint turned(const ProfilePoint& p, double angle) {
  return {std::sin(angle) * p.y + std::cos(angle) * p.z, std::cos(angle) * p.y - std::sin(angle) * p.z, p.x};
}

TEST(FlatChin, PogonionTouchesTheLineFromNasionAndBIsDeepestBehindTheChord) {
  const Eigen::Vector3d nasion(0, 5, 100);  // above the chin, 7 mm behind its bulge
  const auto reading = chin_from_nasion(kinked_symphysis(), nasion, 0);
  ASSERT_TRUE(reading);
  EXPECT_NEAR(reading->pog.z, 10, 0.5);
  EXPECT_NEAR(reading->pog.y, -2, 0.1);
  EXPECT_NEAR(reading->b.z, 20, 0.5);
  EXPECT_NEAR(reading->b.y, 1, 0.1);
  // The concavity's corner lies this far behind the chord from (10, -2) to (30, -3).
  const Eigen::Vector2d along = Eigen::Vector2d(-1, 20).normalized();
  EXPECT_NEAR(reading->b_depth, along.y() * 3 - along.x() * 10, 0.05);
}

TEST(FlatChin, TheReadingTurnsWithTheHead) {
  // Pitched by 8 degrees (the chin's bulge then no longer stands out along y), nasion with it:
  // the same corners, turned.
  const double angle = 8 * 3.14159265358979 / 180;
  Profile front;
  for (const auto& p : kinked_symphysis()) front.push_back(turned(p, angle));
  const ProfilePoint n = turned({100, 5, 0}, angle);
  const auto reading = chin_from_nasion(front, Eigen::Vector3d(0, n.y, n.z), turned({0, 0, 0}, angle).z);
  ASSERT_TRUE(reading);
  const ProfilePoint pog = turned({10, -2, 0}, angle), b = turned({20, 1, 0}, angle);
  EXPECT_LT(std::hypot(reading->pog.z - pog.z, reading->pog.y - pog.y), 0.5);
  EXPECT_LT(std::hypot(reading->b.z - b.z, reading->b.y - b.y), 0.5);
}

TEST(FlatChin, TooShortAProfileIsNoReading) {
  Profile front = kinked_symphysis();
  front.resize(6);
  EXPECT_FALSE(chin_from_nasion(front, Eigen::Vector3d(0, 5, 100), 0));
}

}  // namespace
}  // namespace maxillo::landmarking
