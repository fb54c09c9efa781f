// A stored plan result's moves read back exactly, and a damaged one is an error naming the key.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"
#include "planning/plan_application.h"
#include "support/error_of.h"

namespace maxillo::planning {
namespace {

PlanResult two_moves() {
  PlanResult result;
  PlannedMove maxilla;
  maxilla.segment = Segment::kMaxilla;
  maxilla.pivot = {1.25, -60.5, 3.0};
  maxilla.move.advancement_mm = 6;
  maxilla.move.pitch_deg = -2.5;
  maxilla.transform =
      Eigen::Translation3d(0.1, -6.0, 0.3) * Eigen::AngleAxisd(-0.0436, Eigen::Vector3d(1, 0.2, 0).normalized());
  PlannedMove chin;
  chin.segment = Segment::kChin;
  chin.pivot = {0, -80, -40};
  chin.move.vertical_mm = 3;
  chin.transform = Eigen::Translation3d(0, 0, -3) * Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitX());
  result.moves = {maxilla, chin};
  return result;
}

void read_moves(const Json& json) { planned_moves_from_json(json, "artefact 7 (plan result)"); }

// The message of the error reading `json`'s moves throws, with its code checked.
std::string failure(const Json& json) {
  return testing::error_of([&] { read_moves(json); });
}

TEST(PlannedMovesJson, RoundTripIsExact) {
  const PlanResult result = two_moves();
  // Through text, as the archive stores it.
  const Json stored = Json::parse(plan_result_json(result).dump(2));
  const auto moves = planned_moves_from_json(stored, "test");
  ASSERT_EQ(moves.size(), 2u);
  for (size_t i = 0; i < moves.size(); ++i) {
    EXPECT_EQ(moves[i].segment, result.moves[i].segment);
    EXPECT_EQ(moves[i].pivot, result.moves[i].pivot);
    EXPECT_EQ(moves[i].transform.matrix(), result.moves[i].transform.matrix());  // bit for bit
    EXPECT_EQ(moves[i].move.advancement_mm, result.moves[i].move.advancement_mm);
    EXPECT_EQ(moves[i].move.pitch_deg, result.moves[i].move.pitch_deg);
    EXPECT_EQ(moves[i].move.vertical_mm, result.moves[i].move.vertical_mm);
  }
}

TEST(PlannedMovesJson, DamageIsAnErrorNamingTheArtefactAndTheKey) {
  const Json good = Json::parse(plan_result_json(two_moves()).dump());
  auto damaged = [&](const std::function<void(Json&)>& damage) {
    return testing::error_after_damage(good, damage, read_moves);
  };
  const std::string missing_moves = damaged([](Json& j) { j.erase("moves"); });
  EXPECT_NE(missing_moves.find("artefact 7 (plan result)"), std::string::npos) << missing_moves;
  EXPECT_NE(missing_moves.find("moves: missing"), std::string::npos) << missing_moves;
  EXPECT_NE(damaged([](Json& j) { j["moves"][1].erase("segment"); }).find("moves[1].segment: missing"),
            std::string::npos);
  EXPECT_NE(
      damaged([](Json& j) { j["moves"][0]["segment"] = "jaw"; }).find("moves[0].segment: unknown segment \"jaw\""),
      std::string::npos);
  EXPECT_NE(damaged([](Json& j) { j["moves"][0]["pivot"] = "ANS"; }).find("moves[0].pivot: must be an array of 3"),
            std::string::npos);
  EXPECT_NE(damaged([](Json& j) { j["moves"][0]["move"].erase("yaw_deg"); }).find("moves[0].move.yaw_deg: missing"),
            std::string::npos);
  EXPECT_NE(damaged([](Json& j) {
              j["moves"][1]["move"]["roll_deg"] = "1";
            }).find("moves[1].move.roll_deg: must be a number"),
            std::string::npos);
  EXPECT_NE(damaged([](Json& j) { j["moves"][0]["transform_lps"][0][0] = 2.0; }).find("is not a rigid transform"),
            std::string::npos);
  EXPECT_NE(damaged([](Json& j) { j["moves"][0]["transform_lps"][3][2] = 1.0; }).find("last row must be 0 0 0 1"),
            std::string::npos);
  EXPECT_NE(damaged([](Json& j) { j["moves"][0]["transform_lps"].erase(3); }).find("must be 4 rows of 4 numbers"),
            std::string::npos);
  EXPECT_NE(damaged([](Json& j) { j["moves"][0]["extra"] = 1; }).find("moves[0].extra: unknown key"),
            std::string::npos);
  EXPECT_NE(failure(Json::array()).find("plan result: must be an object"), std::string::npos);
}

}  // namespace
}  // namespace maxillo::planning
