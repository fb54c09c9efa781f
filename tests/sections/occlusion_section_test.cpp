#include "sections/occlusion_section.h"

#include <gtest/gtest.h>

#include <cmath>

namespace maxillo::sections {
namespace {

// A Frankfort-like frame turned 90 degrees from the scanner axes, so a wrong axis shows.
AnatomicalFrame turned_frame() {
  AnatomicalFrame frame;
  frame.anterior = Eigen::Vector3d(1, 0, 0);
  frame.left = Eigen::Vector3d(0, 1, 0);
  frame.superior = frame.anterior.cross(frame.left);  // (0, 0, 1)
  return frame;
}

TEST(AnatomicalMotion, ReadsATranslationAlongTheFrameAxes) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.pretranslate(Eigen::Vector3d(2, -3, 0.5));
  const AnatomicalMotion m = anatomical_motion(motion, turned_frame(), Eigen::Vector3d(10, 20, 30));
  EXPECT_NEAR(m.anterior_mm, 2, 1e-12);
  EXPECT_NEAR(m.left_mm, -3, 1e-12);
  EXPECT_NEAR(m.superior_mm, 0.5, 1e-12);
  EXPECT_NEAR(m.pitch_deg, 0, 1e-12);
  EXPECT_NEAR(m.roll_deg, 0, 1e-12);
  EXPECT_NEAR(m.yaw_deg, 0, 1e-12);
}

TEST(AnatomicalMotion, ARotationAboutTheLeftAxisIsPitchWithTheFrontGoingUp) {
  const AnatomicalFrame frame = turned_frame();
  const Eigen::Vector3d reference(0, 0, 0);
  // anterior x left = superior, so turning the front up is a negative turn about `left`.
  Eigen::Isometry3d motion(Eigen::AngleAxisd(-4 * M_PI / 180, frame.left));
  const AnatomicalMotion m = anatomical_motion(motion, frame, reference);
  EXPECT_NEAR(m.pitch_deg, 4, 1e-9);
  EXPECT_NEAR(m.roll_deg, 0, 1e-9);
  EXPECT_NEAR(m.yaw_deg, 0, 1e-9);
  EXPECT_GT((motion * frame.anterior).dot(frame.superior), 0);  // the front goes up
  // About a point 10 mm anterior of the axis: the chord 2 r sin(a/2), mostly superior.
  const AnatomicalMotion at_front = anatomical_motion(motion, frame, 10 * frame.anterior);
  EXPECT_NEAR(std::hypot(at_front.anterior_mm, at_front.superior_mm), 20 * std::sin(2 * M_PI / 180), 1e-9);
  EXPECT_GT(at_front.superior_mm, 0);
}

TEST(AnatomicalMotion, YawAndRollFollowTheirAxes) {
  const AnatomicalFrame frame = turned_frame();
  const AnatomicalMotion yaw =
      anatomical_motion(Eigen::Isometry3d(Eigen::AngleAxisd(-3 * M_PI / 180, frame.superior)), frame, {0, 0, 0});
  EXPECT_NEAR(yaw.yaw_deg, -3, 1e-9);
  EXPECT_NEAR(yaw.pitch_deg, 0, 1e-9);
  const AnatomicalMotion roll =
      anatomical_motion(Eigen::Isometry3d(Eigen::AngleAxisd(1.5 * M_PI / 180, frame.anterior)), frame, {0, 0, 0});
  EXPECT_NEAR(roll.roll_deg, 1.5, 1e-9);
  EXPECT_NEAR(roll.yaw_deg, 0, 1e-9);
  EXPECT_GT((Eigen::AngleAxisd(1.5 * M_PI / 180, frame.anterior) * frame.left).dot(frame.superior), 0);  // left up
  EXPECT_GT((Eigen::AngleAxisd(3 * M_PI / 180, frame.superior) * frame.anterior).dot(frame.left), 0);    // front left
}

}  // namespace
}  // namespace maxillo::sections
