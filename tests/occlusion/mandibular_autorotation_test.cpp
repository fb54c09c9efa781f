#include "occlusion/mandibular_autorotation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_meshes.h"

namespace maxillo::occlusion {
namespace {

using testing::make_box;

// The hinge is the y axis through the origin. The lower "arch" is a block whose top face
// (z = 0) reaches x = 30; the upper one a block 1 mm above it (z >= 1), wider in x. Closing
// raises the far edge (x = 30) fastest: first contact when 30 sin(a) = 1.
struct HingeCase {
  TriangleMesh lower = make_box({10, -5, -2}, {30, 5, 0});
  TriangleMesh upper = make_box({5, -6, 1}, {45, 6, 3});
  DistanceField lower_field{lower}, upper_field{upper};
  HingeAxis hinge{{0, -50, 0}, {0, 50, 0}};
};

TEST(MandibularAutorotation, StopsAtTheFirstContactAngleInClosedForm) {
  HingeCase c;
  const Eigen::Vector3d pogonion(40, 0, -10);
  const AutorotationResult r =
      autorotate_mandible(c.upper_field, c.lower_field, Eigen::Isometry3d::Identity(), c.hinge, pogonion);
  ASSERT_TRUE(r.contact);
  EXPECT_FALSE(r.already_in_contact);
  const double expected_deg = std::asin(1.0 / 30.0) * 180 / M_PI;  // 1.9101 degrees
  EXPECT_NEAR(r.angle_deg, expected_deg, 0.01);
  EXPECT_LE(r.angle_deg, expected_deg + 1e-9);  // the reported angle is contact-free
  // Pogonion moves along its circle about the hinge: chord 2 r sin(a/2), upwards.
  const double radius = pogonion.norm();
  EXPECT_NEAR(r.pogonion_mm, 2 * radius * std::sin(r.angle_deg * M_PI / 360), 1e-9);
  EXPECT_GT(r.pogonion_displacement.z(), 0);
  // The far edge ends just below the upper block.
  EXPECT_NEAR((r.lower_motion * Eigen::Vector3d(30, 0, 0)).z(), 1.0, 30 * 0.01 * M_PI / 180 + 1e-9);
}

TEST(MandibularAutorotation, FindsTheClosingDirectionWhicheverWayTheAxisPoints) {
  HingeCase c;
  c.hinge = {{0, 50, 0}, {0, -50, 0}};
  const AutorotationResult r =
      autorotate_mandible(c.upper_field, c.lower_field, Eigen::Isometry3d::Identity(), c.hinge, {40, 0, -10});
  ASSERT_TRUE(r.contact);
  EXPECT_NEAR(r.angle_deg, std::asin(1.0 / 30.0) * 180 / M_PI, 0.01);
}

TEST(MandibularAutorotation, ReportsArchesAlreadyInContactAndArchesThatNeverMeet) {
  HingeCase c;
  Eigen::Isometry3d down = Eigen::Isometry3d::Identity();
  down.pretranslate(Eigen::Vector3d(0, 0, -1));  // the upper block now rests on the lower one
  const AutorotationResult touching = autorotate_mandible(c.upper_field, c.lower_field, down, c.hinge, {40, 0, -10});
  EXPECT_TRUE(touching.already_in_contact);
  EXPECT_EQ(touching.angle_deg, 0);

  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.pretranslate(Eigen::Vector3d(200, 0, 0));  // out of reach of the lower block's arc
  AutorotationOptions options;
  options.max_angle_deg = 10;
  const AutorotationResult never =
      autorotate_mandible(c.upper_field, c.lower_field, far, c.hinge, {40, 0, -10}, options);
  EXPECT_FALSE(never.contact);
  EXPECT_NEAR(never.angle_deg, 10, 1e-9);
}

TEST(HingeRotation, KeepsTheAxisPointsFixed) {
  const HingeAxis hinge{{1, 2, 3}, {4, 6, 3}};
  const Eigen::Isometry3d m = hinge_rotation(hinge, 7);
  EXPECT_NEAR((m * hinge.first - hinge.first).norm(), 0, 1e-12);
  EXPECT_NEAR((m * hinge.second - hinge.second).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace maxillo::occlusion
