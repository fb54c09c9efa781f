// A stored validation reads back as one record, and damage to it is an error naming the key.
#include "records/validation_record.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"
#include "casework/validation/validation_json.h"
#include "support/error_of.h"

namespace maxillo::records {
namespace {

validation::DistanceStatistics statistics(int count, double mean_absolute) {
  validation::DistanceStatistics s;
  s.count = count;
  s.mean_absolute = mean_absolute;
  s.mean_signed = -0.25;
  s.standard_deviation = 0.5;
  s.p5 = -1;
  s.p50 = -0.2;
  s.p95 = 0.75;
  s.max_absolute = 1.5;
  s.within_tolerance_percent = 98.5;
  return s;
}

// A validation of case 4 as validation_json writes it: one moved segment, the face and one
// subregion, corresponding points for the face only.
Json stored_validation() {
  casework::CaseValidation v;
  v.case_id = 4;
  v.preop_series = 10;
  v.postop_series = 11;
  v.inputs_hash = std::string(64, 'a');
  v.registration.moving_to_fixed = Eigen::Translation3d(1, 2, 3) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ());
  v.registration.metric = -1.35;
  v.registration.iterations = 26;
  v.registration.seconds = 1.9;
  v.cranium_icp_rms_mm = 0.12;
  casework::SegmentOutcome maxilla;
  maxilla.segment = 2;
  maxilla.planned = Eigen::Translation3d(0, -6, 0) * Eigen::Isometry3d::Identity();
  maxilla.actual = Eigen::Translation3d(0, -5, 0.5) * Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitX());
  maxilla.icp_rms_mm = 0.2;
  maxilla.mean_difference_mm = 1.1;
  maxilla.max_difference_mm = 2.4;
  v.segments = {maxilla};
  v.statistics = {{"face", statistics(20000, 0.6), statistics(20000, 0.7)}, {"upper lip", statistics(900, 1.2), {}}};
  v.seconds = 12.5;
  CaseContents contents;
  contents.record.label = "pre-op";
  return casework::validation_json(v, contents);
}

TEST(ValidationRecord, ReadsBackWhatWasStored) {
  const ValidationRecord record = read_validation_record(Json::parse(stored_validation().dump()), "test");
  EXPECT_EQ(record.format_version, ValidationRecord::kFormatVersion);
  EXPECT_EQ(record.case_id, 4);
  EXPECT_EQ(record.postop_series, 11);
  EXPECT_EQ(record.preop_date, "");  // no study: undated
  EXPECT_EQ(record.registration.iterations, 26);
  EXPECT_DOUBLE_EQ(record.registration.metric, -1.35);
  EXPECT_LT((record.registration.moving_to_fixed.translation() - Eigen::Vector3d(1, 2, 3)).norm(), 1e-12);
  ASSERT_EQ(record.segments.size(), 1u);
  EXPECT_EQ(record.segments[0].segment, "maxilla");
  EXPECT_GT(record.segments[0].rotation_difference_deg, 1.1);  // 0.02 rad
  ASSERT_EQ(record.regions.size(), 2u);
  EXPECT_EQ(record.regions[0].region, "face");
  EXPECT_EQ(record.regions[0].closest.count, 20000);
  ASSERT_TRUE(record.regions[0].corresponding);
  EXPECT_DOUBLE_EQ(record.regions[0].corresponding->mean_absolute, 0.7);
  EXPECT_FALSE(record.regions[1].corresponding);  // not computed: stored as null
}

TEST(ValidationRecord, DamageIsAnErrorNamingTheArtefactAndTheKey) {
  const Json good = stored_validation();
  auto failure = [&](const std::function<void(Json&)>& damage) {
    return testing::error_after_damage(good, damage,
                                       [](const Json& j) { read_validation_record(j, "artefact 31 (validation)"); });
  };
  EXPECT_EQ(failure([](Json& j) { j["registration"].erase("iterations"); }),
            "artefact 31 (validation): registration.iterations: missing");
  EXPECT_EQ(failure([](Json& j) { j["regions"][0]["closest"]["p95"] = "0.7"; }),
            "artefact 31 (validation): regions[0].closest.p95: must be a number");
  EXPECT_EQ(failure([](Json& j) { j["regions"][1].erase("corresponding"); }),
            "artefact 31 (validation): regions[1].corresponding: missing");
  EXPECT_EQ(failure([](Json& j) { j["segments"][0]["actual"][3][3] = 2.0; }),
            "artefact 31 (validation): segments[0].actual: last row must be 0 0 0 1");
  EXPECT_EQ(failure([](Json& j) { j["regions"] = Json::array(); }),
            "artefact 31 (validation): regions: must hold the face's statistics at least");
  EXPECT_EQ(failure([](Json& j) { j.erase("postop_date"); }), "artefact 31 (validation): postop_date: missing");
  EXPECT_EQ(failure([](Json& j) { j["format_version"] = 7; }),
            "artefact 31 (validation): format_version: is 7, newer than this program reads (1): update maxillo");
  Json old = good;
  old.erase("format_version");
  EXPECT_EQ(read_validation_record(old, "old").format_version, 1);
}

}  // namespace
}  // namespace maxillo::records
