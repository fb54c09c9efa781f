// The planning frame and the frame <-> transform conversion: known values and round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "planning/anatomical_moves.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

// A patient-axes frame (anterior -y, left +x, superior +z), as without landmarks.
PlanningFrame axes_frame() { return planning_frame({}); }

TEST(PlanningFrame, WithoutLandmarksIsThePatientAxes) {
  const PlanningFrame frame = axes_frame();
  EXPECT_EQ(frame.source, "patient axes");
  EXPECT_TRUE(frame.anterior.isApprox(Vector3d(0, -1, 0)));
  EXPECT_TRUE(frame.superior.isApprox(frame.anterior.cross(frame.left)));
}

TEST(PlanningFrame, NasionFrameIsSnRotatedSixDegreesDown) {
  // S behind N, SN rising 7 deg anteriorly above the z = 0 Frankfort plane (the phantom's design).
  const double rise = 7 * std::numbers::pi / 180;
  const Vector3d s(0, 0, 20), n = s + 70 * Vector3d(0, -std::cos(rise), std::sin(rise));
  const LandmarkSet landmarks{
      {"S", s}, {"N", n}, {"PoR", {-60, 60, 0}}, {"PoL", {60, 60, 0}}, {"OrR", {-33, -10, 0}}, {"OrL", {33, -10, 0}}};
  const PlanningFrame frame = planning_frame(landmarks);
  EXPECT_EQ(frame.source, "nasion");
  EXPECT_TRUE(frame.origin.isApprox(n));
  // The X axis rises 7 - 6 = 1 deg above Frankfort, anteriorly.
  const double elevation = std::asin(frame.anterior.z()) * 180 / std::numbers::pi;
  EXPECT_NEAR(elevation, 1.0, 1e-9);
  EXPECT_NEAR(frame.anterior.x(), 0, 1e-12);
  EXPECT_NEAR(frame.anterior.cross(frame.left).dot(frame.superior), 1, 1e-12);
}

TEST(FrameMove, PureTranslationsGiveTheirValues) {
  const PlanningFrame frame = axes_frame();
  const Vector3d pivot(0, 30, -20);
  FrameMove move;
  move.advancement_mm = 10;
  Eigen::Isometry3d t = to_transform(frame, move, pivot);
  EXPECT_TRUE((t * pivot - pivot).isApprox(Vector3d(0, -10, 0)));  // forward = -y
  move = {};
  move.vertical_mm = 4;  // extrusion: down
  t = to_transform(frame, move, pivot);
  EXPECT_TRUE((t * pivot - pivot).isApprox(Vector3d(0, 0, -4)));
  move = {};
  move.lateral_mm = 3;  // to the patient's left = +x
  t = to_transform(frame, move, pivot);
  EXPECT_TRUE((t * Vector3d(5, 5, 5) - Vector3d(5, 5, 5)).isApprox(Vector3d(3, 0, 0)));
}

TEST(FrameMove, PureRotationsMoveAPointTheDocumentedWay) {
  const PlanningFrame frame = axes_frame();
  const Vector3d pivot(0, 40, -20);                      // PNS-like
  const Vector3d incisor = pivot + Vector3d(0, -50, 0);  // 50 mm in front of it
  FrameMove move;
  move.pitch_deg = 10;  // anterior end up
  Vector3d moved = to_transform(frame, move, pivot) * incisor;
  EXPECT_NEAR(moved.z() - incisor.z(), 50 * std::sin(10 * std::numbers::pi / 180), 1e-9);
  move = {};
  move.yaw_deg = 5;  // anterior end to the patient's left (+x)
  moved = to_transform(frame, move, pivot) * incisor;
  EXPECT_NEAR(moved.x(), 50 * std::sin(5 * std::numbers::pi / 180), 1e-9);
  move = {};
  move.roll_deg = 3;  // left side up
  moved = to_transform(frame, move, pivot) * (pivot + Vector3d(30, 0, 0));
  EXPECT_NEAR(moved.z() - pivot.z(), 30 * std::sin(3 * std::numbers::pi / 180), 1e-9);
}

TEST(FrameMove, RoundTripsThroughTheTransform) {
  PlanningFrame frame = axes_frame();
  // An oblique frame: the same conventions must hold in any orientation.
  const Eigen::Matrix3d tilt =
      (Eigen::AngleAxisd(0.3, Vector3d::UnitX()) * Eigen::AngleAxisd(-0.2, Vector3d::UnitZ())).toRotationMatrix();
  frame.anterior = tilt * frame.anterior;
  frame.left = tilt * frame.left;
  frame.superior = tilt * frame.superior;
  const Vector3d pivot(3, 40, -25);
  const FrameMove move{
      .advancement_mm = 7.5, .vertical_mm = -2.25, .lateral_mm = 1.5, .pitch_deg = -4, .roll_deg = 2.5, .yaw_deg = 6};
  const FrameMove back = from_transform(frame, to_transform(frame, move, pivot), pivot);
  EXPECT_NEAR(back.advancement_mm, move.advancement_mm, 1e-9);
  EXPECT_NEAR(back.vertical_mm, move.vertical_mm, 1e-9);
  EXPECT_NEAR(back.lateral_mm, move.lateral_mm, 1e-9);
  EXPECT_NEAR(back.pitch_deg, move.pitch_deg, 1e-9);
  EXPECT_NEAR(back.roll_deg, move.roll_deg, 1e-9);
  EXPECT_NEAR(back.yaw_deg, move.yaw_deg, 1e-9);
}

TEST(FrameMove, TransformRoundTripsThroughFrameValues) {
  const PlanningFrame frame = axes_frame();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(0.2, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  t.translation() = Vector3d(1, -8, 2);
  const Vector3d pivot(0, 35, -22);
  const Eigen::Isometry3d back = to_transform(frame, from_transform(frame, t, pivot), pivot);
  EXPECT_TRUE(back.matrix().isApprox(t.matrix(), 1e-12));
}

}  // namespace
}  // namespace maxillo::planning
