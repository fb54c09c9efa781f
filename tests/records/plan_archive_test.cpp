// Plans in a real archive (versions kept as history) and the report's planning section made
// from a plan applied to the phantom.
#include <gtest/gtest.h>

#include <functional>

#include "support/archived_case.h"
#include "core/error.h"
#include "core/sha256.h"
#include "records/plan_archive.h"
#include "casework/plan/plan_outputs.h"
#include "records/plan_result_record.h"
#include "sections/planning_section.h"
#include "planning/plan_application.h"
#include "sample/phantom.h"
#include "support/error_of.h"

namespace maxillo::records {
namespace {

using testing::ArchivedCase;

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
}

// Issue 17: simulate and validate reuse the moves `plan apply` stored, found by the plan's text
// and the landmarks; a result stored for other landmarks or another plan is not theirs.
TEST(PlanArchive, StoredMovesAreFoundForTheirPlanAndLandmarksOnly) {
  ArchivedCase c;
  const Phantom phantom = make_phantom({.spacing_mm = 2.0, .noise_sigma_hu = 0});
  const StoredPlan plan =
      store_plan(c.archive, c.case_id, planning::distraction_plan({.advancement_mm = 8}, "distraction"));
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
  const std::string lost =
      testing::error_of([&] { stored_plan_moves(c.archive, c.case_id, plan.sha256, phantom.landmarks); });
  EXPECT_NE(lost.find("(plan-result): moves: missing"), std::string::npos) << lost;
  // A newer one that is not JSON at all is an error naming it, not a case without a plan result.
  const int64_t text_id = c.archive.add_artefact(
      NewArtefact{c.case_id, "plan-result", c.archive.store_object("{ damaged"), "application/json", "x", "{}"});
  EXPECT_EQ(testing::error_of([&] { latest_plan_result(c.archive, c.case_id); }),
            "artefact " + std::to_string(text_id) + " (plan-result): is not JSON");
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
  const report::Section section =
      sections::planning_section(read_plan_result_record(planning::plan_result_json(result), "test"));
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
  EXPECT_EQ(schedule->rows[0][2], "21.00");  // turns: 20.88 -> 21
  EXPECT_EQ(schedule->rows[0][4], "6");      // first day after 5 days of latency
  EXPECT_EQ(schedule->rows[0][5], "16");     // 11 days

  const report::Table* simulation = table_with_column(section, "Target (LPS mm)");
  ASSERT_NE(simulation, nullptr);
  ASSERT_EQ(simulation->rows.size(), 3u);
  for (const auto& row : simulation->rows) EXPECT_EQ(row[3], "0.00 mm") << row[0];
}

// A plan created and not applied (a real CT whose automatic landmarks are flagged) is shown with
// its target and what applying it needs, not left out of the report.
TEST(PlanningSection, APlanNotAppliedSaysHowToApplyItAndWhatWouldRefuseIt) {
  records::StoredPlan stored;
  stored.version = 2;
  stored.created_at = "2026-11-29T10:00:00Z";
  stored.plan = planning::distraction_plan({.advancement_mm = 6});
  auto text_of = [](const report::Section& section) {
    std::string text;
    for (const auto& block : section.blocks) {
      if (const auto* p = std::get_if<report::Paragraph>(&block)) text += p->text + "\n";
      if (const auto* n = std::get_if<report::Note>(&block)) text += n->text + "\n";
      if (const auto* kv = std::get_if<report::KeyValueBlock>(&block))
        for (const auto& [key, value] : kv->pairs) text += key + ": " + value + "\n";
    }
    return text;
  };
  const std::string flagged = text_of(sections::unapplied_plan_section(stored, 7, {"OrL (mirror: 19.6 mm)"}));
  EXPECT_NE(flagged.find("TS-MD distraction: 6 mm advancement"), std::string::npos) << flagged;
  EXPECT_NE(flagged.find("Target advancement: 6.0 mm"), std::string::npos) << flagged;
  EXPECT_NE(flagged.find("Plan version 2, stored 2026-11-29T10:00:00Z, not applied yet: `maxillo plan apply 7`"),
            std::string::npos)
      << flagged;
  EXPECT_NE(flagged.find("--accept-flagged`: OrL (mirror: 19.6 mm)."), std::string::npos) << flagged;
  const std::string confirmed = text_of(sections::unapplied_plan_section(stored, 7, {}));
  EXPECT_EQ(confirmed.find("refused"), std::string::npos) << confirmed;
}

// Issue 17: a stored plan result is one record read strictly. What the report shows reads back,
// and a result that lost or garbled a field is an error naming the artefact and the key, never a
// zero in the report or a plan read as feasible.
TEST(PlanResultRecord, ReadsBackWhatTheReportShowsAndRefusesDamage) {
  ArchivedCase c;
  const Phantom phantom = make_phantom(PhantomSpec{.spacing_mm = 2.0});
  const StoredPlan plan =
      store_plan(c.archive, c.case_id, planning::distraction_plan({.advancement_mm = 10, .widening_mm = 6}, "test"));
  const planning::PlanResult result = planning::apply_plan(plan.plan, phantom.labels, phantom.landmarks);
  casework::PlanOutputs outputs;
  outputs.segments = {{planning::Segment::kMaxilla, 1234, 5.5}};
  outputs.bone_voxels = 5000;
  const Json stored = plan_result_record_json(result, casework::plan_outputs_json(outputs));
  store_plan_result(c.archive, c.case_id, plan, phantom.landmarks, stored);

  const auto record = latest_plan_result(c.archive, c.case_id);
  ASSERT_TRUE(record);
  EXPECT_EQ(record->format_version, PlanResultRecord::kFormatVersion);
  EXPECT_EQ(record->feasible, result.feasible);
  EXPECT_EQ(record->plan.description, "test");
  ASSERT_TRUE(record->distraction);
  EXPECT_EQ(record->distraction->checks.size(), result.distraction->checks.size());
  EXPECT_EQ(record->distraction->right.activation_mm, result.distraction->vectors.right.activation_mm);
  EXPECT_EQ(record->distraction->schedule.consolidation_end_day, result.distraction->schedule.consolidation_end_day);
  EXPECT_EQ(record->distraction->simulation.size(), result.distraction->simulation.points.size());
  ASSERT_TRUE(record->osteotomy);
  EXPECT_EQ(record->osteotomy->segments.front().segment, "maxilla");
  EXPECT_EQ(record->osteotomy->bone_voxels, 5000);
  EXPECT_FALSE(record->osteotomy->transfer_model);

  auto failure = [&](const std::function<void(Json&)>& damage) {
    return testing::error_after_damage(stored, damage,
                                       [](const Json& j) { read_plan_result_record(j, "artefact 9 (plan result)"); });
  };
  EXPECT_EQ(failure([](Json& j) { j.erase("feasible"); }), "artefact 9 (plan result): feasible: missing");
  EXPECT_EQ(failure([](Json& j) { j["feasible"] = "yes"; }),
            "artefact 9 (plan result): feasible: must be true or false");
  EXPECT_EQ(failure([](Json& j) { j["distraction"]["checks"][3].erase("limit_mm"); }),
            "artefact 9 (plan result): distraction.checks[3].limit_mm: missing");
  EXPECT_EQ(failure([](Json& j) { j["distraction"]["schedule"]["right"]["first_day"] = 1.5; }),
            "artefact 9 (plan result): distraction.schedule.right.first_day: must be an integer");
  EXPECT_EQ(failure([](Json& j) { j["distraction"]["forward_simulation"]["points"][0].erase("target"); }),
            "artefact 9 (plan result): distraction.forward_simulation.points[0].target: missing");
  EXPECT_EQ(failure([](Json& j) { j["osteotomy"]["segments"][0]["voxels"] = "many"; }),
            "artefact 9 (plan result): osteotomy.segments[0].voxels: must be an integer");
  EXPECT_EQ(failure([](Json& j) { j["frame"].erase("source"); }), "artefact 9 (plan result): frame.source: missing");
  EXPECT_EQ(failure([](Json& j) { j["files"]["render"] = 3; }),
            "artefact 9 (plan result): files.render: must be a path");
  EXPECT_EQ(failure([](Json& j) { j["format_version"] = 2; }),
            "artefact 9 (plan result): format_version: is 2, newer than this program reads (1): update maxillo");
  EXPECT_NE(failure([](Json& j) { j["plan"]["moves"] = 4; }).find("artefact 9 (plan result) plan"), std::string::npos);
  // Results stored before the version key existed have the same layout: read as version 1.
  Json old = stored;
  old.erase("format_version");
  EXPECT_EQ(read_plan_result_record(old, "old").format_version, 1);
}

}  // namespace
}  // namespace maxillo::records
