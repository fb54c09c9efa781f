// The plan document: round trip, defaults and clear refusals.
#include <gtest/gtest.h>

#include "core/error.h"
#include "planning/plan.h"

namespace maxillo::planning {
namespace {

std::string reason_of(const std::string& text) {
  try {
    parse_plan(text, "plan.json");
  } catch (const Error& e) {
    EXPECT_EQ(e.subject(), "plan.json");
    EXPECT_EQ(e.code(), ErrorCode::kBadValue);
    return e.reason();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

TEST(PlanJson, RoundTripsEveryField) {
  Plan plan = distraction_plan({.advancement_mm = 10,
                                .vertical_mm = 2,
                                .widening_mm = 6,
                                .midline_shift_mm = -1.5,
                                .rotation_deg = -2,
                                .counter_rotation_deg = 1.5},
                               "must show");
  plan.osteotomies.le_fort_i->variant = LeFortVariant::Low;
  plan.osteotomies.genioplasty = CutSpec{CutSpec::Kind::Plane, LeFortVariant::High,
                                         CutPlane{Eigen::Vector3d(0, -20, -80), Eigen::Vector3d(0, -0.6, -0.8)}};
  plan.moves.push_back(
      {Segment::kChin, Pivot{"", Eigen::Vector3d(0, -15, -85)}, {.advancement_mm = 4, .pitch_deg = 3}});
  plan.distraction->device.screw_length_mm = 28;
  plan.distraction->schedule.consolidation_days = 90;
  plan.distraction->entry_right = Eigen::Vector3d(-27, 20, -13);
  plan.distraction->expected_clockwise_rotation_deg = 2;
  plan.occlusion = {"pairs", "pairs.csv"};

  const std::string text = serialise_plan(plan);
  const Plan back = parse_plan(text, "plan.json");
  EXPECT_EQ(serialise_plan(back), text);
  EXPECT_EQ(back.format_version, kPlanFormatVersion);
  ASSERT_EQ(back.moves.size(), 2u);
  EXPECT_EQ(back.moves[1].segment, Segment::kChin);
  EXPECT_DOUBLE_EQ(back.moves[1].move.pitch_deg, 3);
  EXPECT_EQ(back.osteotomies.le_fort_i->variant, LeFortVariant::Low);
  EXPECT_EQ(back.osteotomies.genioplasty->kind, CutSpec::Kind::Plane);
  EXPECT_DOUBLE_EQ(back.distraction->target.widening_mm, 6);
  EXPECT_DOUBLE_EQ(back.distraction->device.screw_length_mm, 28);
  EXPECT_EQ(back.distraction->schedule.consolidation_days, 90);
  EXPECT_FALSE(back.distraction->entry_left.has_value());
  EXPECT_EQ(back.occlusion.pairs_file, "pairs.csv");
}

TEST(PlanJson, APlanWithoutADescriptionIsDescribedByItsTarget) {
  EXPECT_EQ(distraction_plan({.advancement_mm = 6}).description, "TS-MD distraction: 6 mm advancement");
  EXPECT_EQ(distraction_plan({.advancement_mm = 10, .widening_mm = 6.5}).description,
            "TS-MD distraction: 10 mm advancement, 6.5 mm widening");
  EXPECT_EQ(distraction_plan({.advancement_mm = 6}, "mine").description, "mine");
}

TEST(PlanJson, MinimalPlanTakesTheDefaults) {
  const Plan plan = parse_plan(R"({"format_version": 1, "distraction": {"target": {"advancement_mm": 8}}})", "p");
  ASSERT_TRUE(plan.distraction);
  EXPECT_EQ(plan.distraction->schedule.latency_days, 5);
  EXPECT_DOUBLE_EQ(plan.distraction->schedule.mm_per_turn, 0.5);
  EXPECT_TRUE(plan.moves.empty());
}

TEST(PlanJson, RefusalsNameTheFieldAndTheReason) {
  EXPECT_EQ(reason_of("{}"), "format_version: missing");
  EXPECT_NE(reason_of(R"({"format_version": 2})").find("newer than this program"), std::string::npos);
  EXPECT_EQ(reason_of(R"({"format_version": 1, "moves": [{"segment": "maxila"}]})"),
            "moves[0].segment: unknown segment \"maxila\"");
  EXPECT_EQ(reason_of(R"({"format_version": 1, "moves": [{"segment": "maxilla", "advance_mm": 3}]})"),
            "moves[0].advance_mm: unknown key");
  EXPECT_EQ(reason_of(R"({"format_version": 1, "distraction": {"target": {"widening_mm": -2}}})"),
            "distraction.target.widening_mm: must lie in [0, 30], got -2");
  EXPECT_EQ(reason_of(R"({"format_version": 1, "moves": [{"segment": "cranium"}]})"),
            "moves[0].segment: the cranium is the fixed reference and cannot move");
  EXPECT_NE(
      reason_of(R"({"format_version": 1, "osteotomies": {"le_fort_i": {"point": [0, 0, 0], "normal": [0, 0, 0]}}})")
          .find("osteotomies.le_fort_i.normal"),
      std::string::npos);
  EXPECT_NE(reason_of(R"({"format_version": 1, "moves": [{"segment": "maxilla", "advancement_mm": 5}],
                          "distraction": {"target": {"advancement_mm": 10}}})")
                .find("must equal distraction.target"),
            std::string::npos);
  EXPECT_NE(reason_of("{not json").find("invalid JSON"), std::string::npos);
  EXPECT_EQ(reason_of(R"({"format_version": 1, "distraction": {"schedule": {"rate_mm_per_day": "fast"}}})"),
            "distraction.schedule.rate_mm_per_day: must be a number");
}

}  // namespace
}  // namespace maxillo::planning

#include "sample/phantom.h"

namespace maxillo::planning {
namespace {

TEST(PlanOsteotomies, DefaultsResolveFromTheLandmarksAndPlanesPassThrough) {
  const LandmarkSet landmarks = make_phantom({.spacing_mm = 4.0, .noise_sigma_hu = 0}).landmarks;
  Plan plan = distraction_plan({.advancement_mm = 10});
  plan.osteotomies.genioplasty = CutSpec{CutSpec::Kind::Plane, LeFortVariant::High,
                                         CutPlane{Eigen::Vector3d(0, -20, -80), Eigen::Vector3d(0, 0, -1)}};
  const Osteotomies cuts = resolve_osteotomies(plan.osteotomies, landmarks);
  ASSERT_TRUE(cuts.le_fort_i && cuts.pterygomaxillary && cuts.genioplasty);
  const CutPlane expected = default_le_fort_i(landmarks, LeFortVariant::High);
  EXPECT_TRUE(cuts.le_fort_i->point.isApprox(expected.point));
  EXPECT_TRUE(cuts.le_fort_i->normal.isApprox(expected.normal));
  EXPECT_TRUE(cuts.pterygomaxillary->point.isApprox(default_pterygomaxillary(landmarks).point));
  EXPECT_TRUE(cuts.genioplasty->point.isApprox(Eigen::Vector3d(0, -20, -80)));
  EXPECT_FALSE(cuts.bsso_right.has_value());
}

TEST(PlanOsteotomies, ACutGivenByThreePointsFacesTheMovingSegment) {
  const LandmarkSet landmarks = make_phantom({.spacing_mm = 4.0, .noise_sigma_hu = 0}).landmarks;
  const std::string text = R"({"format_version": 1, "osteotomies": {
      "le_fort_i": {"points": [[-20, -60, -18], [20, -60, -18], [0, -20, -18]]},
      "bsso_right": "default", "bsso_left": "default"}})";
  const Plan plan = parse_plan(text, "plan.json");
  ASSERT_EQ(plan.osteotomies.le_fort_i->kind, CutSpec::Kind::Points);
  const Osteotomies cuts = resolve_osteotomies(plan.osteotomies, landmarks);
  // The plane z = -18, its normal pointing down to the teeth (U1 is on the side that moves).
  EXPECT_NEAR(cuts.le_fort_i->point.z(), -18, 1e-9);
  EXPECT_TRUE(cuts.le_fort_i->normal.isApprox(Eigen::Vector3d(0, 0, -1)));
  EXPECT_GT(cuts.le_fort_i->side(*find_landmark(landmarks, "U1")), 0);
  // The BSSO defaults: coronal planes, the distal mandible (L1) in front of both.
  ASSERT_TRUE(cuts.bsso_right && cuts.bsso_left);
  EXPECT_GT(cuts.bsso_right->side(*find_landmark(landmarks, "L1")), 0);
  EXPECT_GT(cuts.bsso_left->side(*find_landmark(landmarks, "L1")), 0);
  // Round trip keeps the points.
  const Plan again = parse_plan(serialise_plan(plan), "again.json");
  EXPECT_TRUE(again.osteotomies.le_fort_i->points[2].isApprox(Eigen::Vector3d(0, -20, -18)));
}

TEST(PlanOsteotomies, CollinearPointsAndOneSidedSplitsAreRefused) {
  EXPECT_THROW(
      parse_plan(
          R"({"format_version": 1, "osteotomies": {"le_fort_i": {"points": [[0, 0, 0], [1, 0, 0], [2, 0, 0]]}}})",
          "plan.json"),
      Error);
  EXPECT_THROW(parse_plan(R"({"format_version": 1, "osteotomies": {"bsso_right": "default"}})", "plan.json"), Error);
}

}  // namespace
}  // namespace maxillo::planning
