// Distractor placement and checks on the phantom (2 mm voxels to stay fast).
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "planning/distractor_checks.h"
#include "planning/forward_simulation.h"
#include "sample/phantom.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

const Phantom& phantom() {
  static const Phantom p = make_phantom({.spacing_mm = 2.0, .noise_sigma_hu = 0});
  return p;
}

Vector3d landmark(const std::string& label) { return *find_landmark(phantom().landmarks, label); }

struct Placed {
  PlanningFrame frame;
  DistractionVectors vectors;
};

// Entry points on the anterior maxillary walls, then the vectors (as plan application does).
Placed place(const MaxillaryTarget& target, const LabelVolume& labels) {
  Placed placed;
  placed.frame = planning_frame(phantom().landmarks);
  const MaxillaryReference ref{landmark("PNS"), landmark("U1")};
  const EntryPoints entries = find_entry_points(labels, placed.frame, {}, phantom().landmarks);
  placed.vectors = distraction_vectors(placed.frame, target, ref, entries.right, entries.left);
  return placed;
}

const DistractorCheck* find_check(const std::vector<DistractorCheck>& checks, const std::string& name, Side side) {
  for (const DistractorCheck& c : checks)
    if (c.name == name && c.side == side) return &c;
  return nullptr;
}

TEST(DistractorChecks, EntryPointsLieOnTheAnteriorMaxillaryWall) {
  const Placed placed = place({.advancement_mm = 10}, phantom().labels);
  // The phantom's sinuses: centres (+-27.5, -40, -13) mm, 17.5 mm antero-posterior semi-axis,
  // walls >= 2.5 mm: the anterior wall's outer surface is near y = -60 (LPS: anterior is -y).
  for (const Vector3d& e : {placed.vectors.right.entry, placed.vectors.left.entry}) {
    EXPECT_NEAR(std::abs(e.x()), 27.5, 2.5);
    EXPECT_NEAR(e.y(), -60, 3.5);
    EXPECT_NEAR(e.z(), -13, 2.5);
  }
}

TEST(DistractorChecks, TheMustShowPlanPassesEveryCheck) {
  const Placed placed = place({.advancement_mm = 10, .widening_mm = 6}, phantom().labels);
  const auto checks = check_distractors(phantom().labels, placed.vectors, phantom().landmarks, placed.frame);
  EXPECT_EQ(checks.size(), 10u);
  for (const DistractorCheck& c : checks)
    EXPECT_NE(c.status, CheckStatus::Fail) << c.name << " " << side_name(c.side) << ": " << c.reason;
  EXPECT_TRUE(all_passed(checks));
}

TEST(DistractorChecks, AScrewLongerThanTheSinusIsRefusedWithItsReason) {
  const Placed placed = place({.advancement_mm = 10}, phantom().labels);
  const auto checks = check_distractors(phantom().labels, placed.vectors, phantom().landmarks, placed.frame, {},
                                        {.screw_length_mm = 42});
  EXPECT_FALSE(all_passed(checks));
  const DistractorCheck* depth = find_check(checks, "sinus depth", Side::Right);
  ASSERT_NE(depth, nullptr);
  EXPECT_EQ(depth->status, CheckStatus::Fail);
  EXPECT_NE(depth->reason.find("deep along the screw axis"), std::string::npos) << depth->reason;
  EXPECT_EQ(find_check(checks, "screw in sinus", Side::Left)->status, CheckStatus::Fail);
}

TEST(DistractorChecks, ATooLongActivationExceedsTheScrewTravel) {
  const Placed placed = place({.advancement_mm = 24}, phantom().labels);
  const auto checks = check_distractors(phantom().labels, placed.vectors, phantom().landmarks, placed.frame);
  EXPECT_EQ(find_check(checks, "screw travel", Side::Left)->status, CheckStatus::Fail);
}

TEST(DistractorChecks, AScrewThroughAToothRootIsRefused) {
  // Move the right entry point down onto the canine/premolar roots: the screw then runs through them.
  Placed placed = place({.advancement_mm = 10}, phantom().labels);
  placed.vectors.right.entry = landmark("U6R") + Vector3d(0, -12, 12);
  const auto checks = check_distractors(phantom().labels, placed.vectors, phantom().landmarks, placed.frame);
  const DistractorCheck* teeth = find_check(checks, "tooth distance", Side::Right);
  ASSERT_NE(teeth, nullptr);
  EXPECT_EQ(teeth->status, CheckStatus::Fail);
  EXPECT_NE(teeth->reason.find("tooth root or bud"), std::string::npos);
  EXPECT_EQ(find_check(checks, "tooth distance", Side::Left)->status, CheckStatus::Pass);
}

TEST(DistractorChecks, NoSinusAirMeansNoPlan) {
  LabelVolume erased = phantom().labels;
  std::replace(erased.labels.begin(), erased.labels.end(), uint8_t{4}, uint8_t{2});  // sinus air -> bone
  try {
    find_entry_points(erased, planning_frame(phantom().landmarks), {}, phantom().landmarks);
    FAIL() << "expected the plan to be refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kUnsafePlan);
    EXPECT_NE(e.reason().find("no sinus air"), std::string::npos);
  }
}

TEST(DistractorChecks, ForwardSimulationOnThePhantomIsWithinHalfAMillimetre) {
  const MaxillaryTarget target{.advancement_mm = 10, .widening_mm = 6};
  const Placed placed = place(target, phantom().labels);
  const LandmarkSet points{{"ANS", landmark("ANS")}, {"PNS", landmark("PNS")}, {"U1", landmark("U1")}};
  const ForwardSimulation sim =
      simulate_distraction(placed.frame, target, {landmark("PNS"), landmark("U1")}, placed.vectors, points);
  ASSERT_EQ(sim.points.size(), 3u);
  EXPECT_LT(sim.max_error_mm, 0.5);
}

}  // namespace
}  // namespace maxillo::planning
