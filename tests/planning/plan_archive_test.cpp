// Plans in a real archive (versions kept as history) and the report's planning section made
// from a plan applied to the phantom.
#include <gtest/gtest.h>

#include "archive/archive_fixture.h"
#include "core/error.h"
#include "core/sha256.h"
#include "pipeline/plan_archive.h"
#include "pipeline/planning_section.h"
#include "planning/plan_application.h"
#include "sample/phantom.h"

namespace maxillo::pipeline {
namespace {

struct ArchivedCase {
  maxillo::testing::TemporaryFolder folder;
  Archive archive = Archive::open(folder.path() / "archive", OpenMode::CreateIfMissing);
  int64_t case_id = 0;
  ArchivedCase() {
    maxillo::testing::write_series(folder.path() / "dicom", 3, "P9");
    archive.import_paths({folder.path() / "dicom"});
    case_id = archive.resolve_case("P9");
  }
};

TEST(PlanArchive, EverySavedPlanIsANewVersion) {
  ArchivedCase c;
  EXPECT_FALSE(latest_plan(c.archive, c.case_id));
  store_plan(c.archive, c.case_id, planning::distraction_plan({.advancement_mm = 8}, "first"));
  const StoredPlan second =
      store_plan(c.archive, c.case_id, planning::distraction_plan({.advancement_mm = 10, .widening_mm = 6}, "second"));
  EXPECT_EQ(second.version, 2);
  const auto history = plan_history(c.archive, c.case_id);
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[0].version, 1);
  EXPECT_EQ(history[0].plan.description, "first");
  EXPECT_DOUBLE_EQ(history[0].plan.distraction->target.advancement_mm, 8);
  EXPECT_EQ(latest_plan(c.archive, c.case_id)->plan.description, "second");
  EXPECT_DOUBLE_EQ(latest_plan(c.archive, c.case_id)->plan.distraction->target.widening_mm, 6);

  EXPECT_FALSE(latest_plan_result(c.archive, c.case_id));
  store_plan_result(c.archive, c.case_id, second, {}, Json{{"feasible", true}});
  EXPECT_EQ(latest_plan_result(c.archive, c.case_id)->at("feasible"), true);
}

// Issue 17: simulate and validate reuse the moves `plan apply` stored, found by the plan's text
// and the landmarks; a result stored for other landmarks or another plan is not theirs.
TEST(PlanArchive, StoredMovesAreFoundForTheirPlanAndLandmarksOnly) {
  ArchivedCase c;
  const Phantom phantom = make_phantom({.spacing_mm = 2.0, .noise_sigma_hu = 0});
  const StoredPlan plan = store_plan(c.archive, c.case_id, planning::distraction_plan({.advancement_mm = 8}, "distraction"));
  const planning::PlanResult applied = planning::apply_plan(plan.plan, phantom.labels, phantom.landmarks);
  ASSERT_FALSE(applied.moves.empty());
  EXPECT_FALSE(stored_plan_moves(c.archive, c.case_id, plan.sha256, phantom.landmarks));
  store_plan_result(c.archive, c.case_id, plan, phantom.landmarks, planning::plan_result_json(applied));

  const auto moves = stored_plan_moves(c.archive, c.case_id, plan.sha256, phantom.landmarks);
  ASSERT_TRUE(moves);
  ASSERT_EQ(moves->size(), applied.moves.size());
  EXPECT_EQ(moves->front().transform.matrix(), applied.moves.front().transform.matrix());
  EXPECT_EQ(plan.sha256, sha256_hex(planning::serialise_plan(plan.plan)));  // how simulate names a plan

  LandmarkSet moved = phantom.landmarks;
  moved.front().position.x() += 0.5;
  EXPECT_FALSE(stored_plan_moves(c.archive, c.case_id, plan.sha256, moved));
  EXPECT_FALSE(stored_plan_moves(c.archive, c.case_id, std::string(64, '0'), phantom.landmarks));

  // A newer result for the same plan and landmarks that lost its moves is an error, not a re-application.
  store_plan_result(c.archive, c.case_id, plan, phantom.landmarks, Json{{"feasible", true}});
  try {
    stored_plan_moves(c.archive, c.case_id, plan.sha256, phantom.landmarks);
    ADD_FAILURE() << "a stored result without moves was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kArchiveCorrupt);
    EXPECT_NE(std::string(e.what()).find("(plan result): moves: missing"), std::string::npos) << e.what();
  }
}

const report::Table* table_with_column(const report::Section& section, const std::string& title) {
  for (const auto& block : section.blocks)
    if (const auto* table = std::get_if<report::Table>(&block))
      if (!table->columns.empty() && table->columns[1].title == title) return table;
  return nullptr;
}

TEST(PlanningSection, ShowsVectorsChecksScheduleAndSimulation) {
  const Phantom phantom = make_phantom({.spacing_mm = 2.0, .noise_sigma_hu = 0});
  const planning::Plan plan = planning::distraction_plan({.advancement_mm = 10, .widening_mm = 6}, "must show");
  const planning::PlanResult result = planning::apply_plan(plan, phantom.labels, phantom.landmarks);
  ASSERT_TRUE(result.feasible);
  const report::Section section = planning_section(planning::plan_result_json(result));
  EXPECT_EQ(section.id, "planning");

  const report::Table* vectors = table_with_column(section, "Entry point (LPS mm)");
  ASSERT_NE(vectors, nullptr);
  ASSERT_EQ(vectors->rows.size(), 2u);
  EXPECT_EQ(vectors->rows[0][0], "right");
  EXPECT_EQ(vectors->rows[0][2], "16.7\u00b0");  // outward: atan(3 / 10)
  EXPECT_EQ(vectors->rows[0][4], "10.44 mm");    // sqrt(10^2 + 3^2)
  EXPECT_EQ(vectors->rows[1][4], "10.44 mm");

  const report::Table* checks = table_with_column(section, "Check");
  ASSERT_NE(checks, nullptr);
  EXPECT_EQ(checks->rows.size(), 10u);
  for (const auto& row : checks->rows) EXPECT_EQ(row[2], "pass") << row[1];

  const report::Table* schedule = table_with_column(section, "Planned");
  ASSERT_NE(schedule, nullptr);
  EXPECT_EQ(schedule->rows[0][2], "21.00");   // turns: 20.88 -> 21
  EXPECT_EQ(schedule->rows[0][4], "6");       // first day after 5 days of latency
  EXPECT_EQ(schedule->rows[0][5], "16");      // 11 days

  const report::Table* simulation = table_with_column(section, "Target (LPS mm)");
  ASSERT_NE(simulation, nullptr);
  ASSERT_EQ(simulation->rows.size(), 3u);
  for (const auto& row : simulation->rows) EXPECT_EQ(row[3], "0.00 mm") << row[0];
}

// A stored result that lost its "feasible" flag is an error naming it, never reported as feasible.
TEST(PlanningSection, AResultWithoutItsFeasibleFlagIsAnError) {
  const Phantom phantom = make_phantom(PhantomSpec{.spacing_mm = 2.0});
  const planning::PlanResult result = planning::apply_plan(
      planning::distraction_plan({.advancement_mm = 10, .widening_mm = 6}, "test"), phantom.labels, phantom.landmarks);
  Json damaged = planning::plan_result_json(result);
  damaged.erase("feasible");
  try {
    planning_section(damaged);
    ADD_FAILURE() << "a result without \"feasible\" was reported";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::kArchiveCorrupt);
    EXPECT_NE(error.reason().find("feasible"), std::string::npos);
  }
  damaged["feasible"] = "yes";
  EXPECT_THROW(planning_section(damaged), Error);
}

}  // namespace
}  // namespace maxillo::pipeline
