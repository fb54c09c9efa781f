// The checks of a detected landmark set: the template head passes every one; each kind of
// fault (a lopsided pair, an order the anatomy forbids, a size outside adult ranges, a point found
// elsewhere from a second start) fails the check that names it, on the landmarks concerned.
#include <gtest/gtest.h>

#include <cmath>

#include "landmarking/head_volume.h"
#include "landmarking/landmark_checks.h"
#include "landmarking/landmark_template.h"

namespace maxillo::landmarking {
namespace {

FramePoints template_head() {
  FramePoints points;
  for (const auto& label : detected_labels()) points[label] = expected_position(label, 1.0);
  return points;
}

// The failed checks of `label`, by name.
std::vector<std::string> failed(const std::map<std::string, std::vector<CheckOutcome>>& checks,
                                const std::string& label) {
  std::vector<std::string> names;
  if (auto it = checks.find(label); it != checks.end())
    for (const auto& c : it->second)
      if (!c.passed) names.push_back(c.name + " (" + c.detail + ")");
  return names;
}

TEST(LandmarkChecks, TheTemplateHeadPassesEveryCheck) {
  const auto checks = check_landmarks(template_head(), 1.0);
  int count = 0;
  for (const auto& [label, outcomes] : checks) {
    count += int(outcomes.size());
    EXPECT_TRUE(failed(checks, label).empty()) << label << ": " << failed(checks, label).front();
  }
  EXPECT_GE(count, 40);  // mirror, order and range checks were all run
}

TEST(LandmarkChecks, ALopsidedPairFailsItsMirrorCheck) {
  FramePoints points = template_head();
  points["OrL"].z() += 8;
  const auto checks = check_landmarks(points, 1.0);
  ASSERT_EQ(failed(checks, "OrL").size(), 1u);
  EXPECT_NE(failed(checks, "OrL").front().find("mirror"), std::string::npos);
  EXPECT_EQ(failed(checks, "OrR").size(), 1u);
  EXPECT_TRUE(failed(checks, "PoL").empty());
}

// A chin deviated 3 mm to the left carries the lower arch with it: the lower molars, 6 mm from
// each other's mirror image about the skull's plane, mirror about the mandible's midline. A lower
// molar off on its own is still caught.
TEST(LandmarkChecks, TheLowerMolarsMirrorAboutTheMandiblesMidline) {
  FramePoints points = template_head();
  for (const char* label : {"L6R", "L6L", "L1", "B", "Pog", "Me"}) points[label].x() += 3;
  auto checks = check_landmarks(points, 1.0);
  EXPECT_TRUE(failed(checks, "L6R").empty()) << failed(checks, "L6R").front();
  EXPECT_TRUE(failed(checks, "L6L").empty()) << failed(checks, "L6L").front();
  // The same molars with the mandible's midline left where the skull's is: 6 mm apart.
  for (const char* label : {"L1", "B", "Pog", "Me"}) points[label].x() -= 3;
  checks = check_landmarks(points, 1.0);
  ASSERT_EQ(failed(checks, "L6L").size(), 1u);
  EXPECT_NE(failed(checks, "L6L").front().find("mirror"), std::string::npos);
  // One molar 6 mm behind its mirror image about a deviated mandible's midline.
  points = template_head();
  for (const char* label : {"L6R", "L6L", "L1", "B", "Pog", "Me"}) points[label].x() += 3;
  points["L6L"].y() += 6;
  checks = check_landmarks(points, 1.0);
  ASSERT_EQ(failed(checks, "L6R").size(), 1u);
  EXPECT_NE(failed(checks, "L6R").front().find("mandible's midline"), std::string::npos);
  // A cone-beam field whose floor cut the chin: no B, Pog or Me. The lower incisors' contact,
  // half a crown's width to the left of L1 (the right central incisor, itself 2.5 mm off the
  // midline), stands for the midline: the arch deviated 3 mm passes, a molar off on its own fails.
  points = template_head();
  for (const char* label : {"B", "Pog", "Me"}) points.erase(label);
  for (const char* label : {"L6R", "L6L", "L1"}) points[label].x() += 3;
  checks = check_landmarks(points, 1.0);
  EXPECT_TRUE(failed(checks, "L6R").empty()) << failed(checks, "L6R").front();
  points["L6L"].y() += 6;
  checks = check_landmarks(points, 1.0);
  ASSERT_EQ(failed(checks, "L6R").size(), 1u);
  EXPECT_NE(failed(checks, "L6R").front().find("lower incisors' midline"), std::string::npos);
  // Nothing of the lower arch's middle found: the skull's plane.
  points.erase("L1");
  points["L6L"].y() -= 6;
  checks = check_landmarks(points, 1.0);
  ASSERT_EQ(failed(checks, "L6L").size(), 1u) << "3 mm to the left of the skull's plane: 6 mm from the mirror image";
}

TEST(LandmarkChecks, AnOrderTheAnatomyForbidsIsNamed) {
  FramePoints points = template_head();
  points["Me"].z() = points["Pog"].z() + 3;  // menton above pogonion
  const auto checks = check_landmarks(points, 1.0);
  bool named = false;
  for (const auto& f : failed(checks, "Me")) named |= f.find("Me below Pog") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(LandmarkChecks, SizesOutsideAdultRangesAreFlagged) {
  FramePoints points = template_head();
  points["N"] = points["S"] + 1.4 * (points["N"] - points["S"]);  // S-N 97 mm
  const auto checks = check_landmarks(points, 1.0);
  bool named = false;
  for (const auto& f : failed(checks, "N")) named |= f.find("range: S-N") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(LandmarkChecks, AClassThreeBiteMayHaveTheLowerIncisorInFront) {
  FramePoints points = template_head();
  std::swap(points["U1"].y(), points["L1"].y());                     // reverse overjet
  EXPECT_FALSE(failed(check_landmarks(points, 1.0), "U1").empty());  // with Class I jaws: flagged
  points["B"].y() -= 8;                                              // mandible forward: ANB < 0
  points["Pog"].y() -= 8;
  points["PogS"].y() -= 8;
  EXPECT_TRUE(failed(check_landmarks(points, 1.0), "U1").empty());
}

// The second start: a point found again within the limit passes, one farther away or not found
// again fails, saying how far.
TEST(LandmarkChecks, APointFoundElsewhereFromASecondStartFails) {
  const Eigen::Vector3d first(10, -60, -20);
  EXPECT_TRUE(second_start_check(first, first + Eigen::Vector3d(0.9, 0, 1.1)).passed);     // 1.42 mm
  EXPECT_FALSE(second_start_check(first, first + Eigen::Vector3d(0, 1.28, 0.96)).passed);  // 1.6 mm
  const CheckOutcome lost = second_start_check(first, first + Eigen::Vector3d(0, 0, 4));
  EXPECT_FALSE(lost.passed);
  EXPECT_EQ(lost.name, "second start");
  EXPECT_NE(lost.detail.find("4.0 mm"), std::string::npos) << lost.detail;
  EXPECT_FALSE(second_start_check(first, std::nullopt).passed);
}

// The rules' sampling grids start on multiples of their step, wherever their window does.
TEST(LandmarkChecks, TwoOverlappingWindowsShareTheirGridNodes) {
  const double step = 0.5;
  const Eigen::Vector3d lo(-16.3, 7.9, -72.26);
  const Eigen::Vector3d a = grid_corner(lo, step), b = grid_corner({-14.1, 5.2, -70.0}, step);
  EXPECT_TRUE(a.isApprox(Eigen::Vector3d(-16.5, 7.5, -72.5)));
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_LE(a[axis], lo[axis]);
    const double nodes_apart = (b[axis] - a[axis]) / step;
    EXPECT_NEAR(nodes_apart, std::round(nodes_apart), 1e-9) << axis;
  }
}

}  // namespace
}  // namespace maxillo::landmarking
