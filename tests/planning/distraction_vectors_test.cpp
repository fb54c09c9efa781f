// Distraction vectors and the forward simulation against analytic answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "planning/distraction_vectors.h"
#include "planning/forward_simulation.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

// Patient-axes frame through the mid-sagittal plane x = 0; a maxilla like the phantom's.
const PlanningFrame kFrame = planning_frame({});
const Vector3d kPns(0, 45, -25), kAns(0, -5, -22), kU1(-4, -8, -45);
const Vector3d kEntryRight(-27, 20, -15), kEntryLeft(27, 20, -15);
const MaxillaryReference kRef{kPns, kU1};
const LandmarkSet kPoints{{"ANS", kAns}, {"PNS", kPns}, {"U1", kU1}};

TEST(DistractionVectors, AdvancementOnlyGivesParallelVectorsOfTheAdvancement) {
  const MaxillaryTarget target{.advancement_mm = 8};
  const DistractionVectors v = distraction_vectors(kFrame, target, kRef, kEntryRight, kEntryLeft);
  EXPECT_NEAR(v.right.activation_mm, 8, 1e-9);
  EXPECT_NEAR(v.left.activation_mm, 8, 1e-9);
  EXPECT_NEAR(v.angle_deg, 0, 1e-6);
  EXPECT_NEAR(v.divergence_deg, 0, 1e-9);
  EXPECT_TRUE(v.right.axis.isApprox(kFrame.anterior));
  EXPECT_TRUE(v.left.axis.isApprox(kFrame.anterior));
}

TEST(DistractionVectors, WideningDivergesByTheAnalyticAngle) {
  const MaxillaryTarget target{.advancement_mm = 10, .widening_mm = 6};
  // The divergence does not depend on how far apart the distractors sit.
  for (double half_separation : {15.0, 27.0, 40.0}) {
    const Vector3d right(-half_separation, 20, -15), left(half_separation, 20, -15);
    const DistractionVectors v = distraction_vectors(kFrame, target, kRef, right, left);
    const double expected = 2 * std::atan(6.0 / (2 * 10)) * 180 / std::numbers::pi;  // 33.40 deg
    EXPECT_NEAR(v.divergence_deg, expected, 1e-9);
    EXPECT_NEAR(v.angle_deg, expected, 1e-9);
    EXPECT_NEAR(divergence_for_widening_deg(10, 6), expected, 1e-12);
    EXPECT_NEAR(v.right.outward_deg, expected / 2, 1e-9);
    EXPECT_NEAR(v.right.activation_mm, std::sqrt(100.0 + 9.0), 1e-9);
    // The entry points end up 6 mm further apart than they started.
    const Vector3d r_end = right + v.right.activation_mm * v.right.axis;
    const Vector3d l_end = left + v.left.activation_mm * v.left.axis;
    EXPECT_NEAR((l_end - r_end).x() - (left - right).x(), 6, 1e-9);
  }
}

TEST(DistractionVectors, MidlineShiftNeedsUnequalActivation) {
  // Shift the incisor midline 3 mm to the patient's left: the right side advances more.
  const MaxillaryTarget target{.advancement_mm = 8, .midline_shift_mm = 3};
  const DistractionVectors v = distraction_vectors(kFrame, target, kRef, kEntryRight, kEntryLeft);
  EXPECT_GT(v.right.activation_mm, v.left.activation_mm + 1);
  const double yaw = midline_yaw_deg(kFrame, target, kRef);
  EXPECT_NEAR(std::sin(yaw * std::numbers::pi / 180) * 53, 3, 1e-9);  // U1 is 53 mm in front of PNS
  // The difference of the advancements is the yaw times the entry points' separation.
  const double expected_difference = 54 * std::sin(yaw * std::numbers::pi / 180);
  EXPECT_NEAR((v.right.activation_mm * v.right.axis - v.left.activation_mm * v.left.axis).dot(kFrame.anterior),
              expected_difference, 1e-9);
}

TEST(DistractionVectors, VerticalChangeInclinesBothVectors) {
  const MaxillaryTarget target{.advancement_mm = 10, .vertical_mm = 3};  // 3 mm down
  const DistractionVectors v = distraction_vectors(kFrame, target, kRef, kEntryRight, kEntryLeft);
  EXPECT_NEAR(v.right.elevation_deg, -std::atan2(3, 10) * 180 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(v.left.activation_mm, std::hypot(10, 3), 1e-9);
}

TEST(DistractionVectors, CounterRotationTiltsTheAxesUpKeepingTheirLength) {
  const MaxillaryTarget target{.advancement_mm = 10, .counter_rotation_deg = 4};
  const DistractionVectors v = distraction_vectors(kFrame, target, kRef, kEntryRight, kEntryLeft);
  EXPECT_NEAR(v.right.elevation_deg, 4, 1e-9);
  EXPECT_NEAR(v.right.activation_mm, 10, 1e-9);
}

TEST(ForwardSimulation, TenMillimetreAdvancementWithSixMillimetreWideningHitsTheTarget) {
  const MaxillaryTarget target{.advancement_mm = 10, .widening_mm = 6};
  const DistractionVectors v = distraction_vectors(kFrame, target, kRef, kEntryRight, kEntryLeft);
  const ForwardSimulation sim = simulate_distraction(kFrame, target, kRef, v, kPoints);
  ASSERT_EQ(sim.points.size(), 3u);
  for (const SimulatedPoint& p : sim.points) EXPECT_LT(p.error_mm, 0.5) << p.label;
  EXPECT_NEAR(sim.achieved.advancement_mm, 10, 1e-6);
  EXPECT_NEAR(sim.achieved_widening_mm, 6, 1e-6);
  // ANS moves 10 mm forward; U1 (right half) also 3 mm to the right.
  EXPECT_TRUE((sim.points[0].simulated - kAns).isApprox(Vector3d(0, -10, 0), 1e-6));
  EXPECT_TRUE((sim.points[2].simulated - kU1).isApprox(Vector3d(-3, -10, 0), 1e-6));
}

TEST(ForwardSimulation, CombinedMovesAreRecovered) {
  const MaxillaryTarget target{
      .advancement_mm = 9, .vertical_mm = 2, .widening_mm = 4, .midline_shift_mm = -2, .rotation_deg = -3};
  const DistractionVectors v = distraction_vectors(kFrame, target, kRef, kEntryRight, kEntryLeft);
  const ForwardSimulation sim = simulate_distraction(kFrame, target, kRef, v, kPoints);
  EXPECT_LT(sim.max_error_mm, 1e-6);
}

TEST(ForwardSimulation, AnUncompensatedClockwiseDriftMissesTheIncisorAndCounterRotationReducesIt) {
  const MaxillaryTarget target{.advancement_mm = 10};
  const DistractionVectors plain = distraction_vectors(kFrame, target, kRef, kEntryRight, kEntryLeft);
  const ForwardSimulation drifted = simulate_distraction(kFrame, target, kRef, plain, kPoints, 3);
  EXPECT_GT(drifted.max_error_mm, 0.5);
  MaxillaryTarget countered = target;
  countered.counter_rotation_deg = 3;
  const DistractionVectors tilted = distraction_vectors(kFrame, countered, kRef, kEntryRight, kEntryLeft);
  const ForwardSimulation compensated = simulate_distraction(kFrame, target, kRef, tilted, kPoints, 3);
  EXPECT_LT(compensated.points[2].error_mm, drifted.points[2].error_mm);  // U1
}

}  // namespace
}  // namespace maxillo::planning
