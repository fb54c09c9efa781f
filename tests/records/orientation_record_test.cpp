// The orientation record (records/orientation_record.h): a strict reader, a round trip through
// the archive, the newest record of a CT content winning, and what a listing shows of it.
#include <gtest/gtest.h>

#include "archive_fixture.h"
#include "records/orientation_record.h"
#include "support/error_of.h"

namespace maxillo::records {
namespace {

using testing::TemporaryFolder;

OrientationRecord flagged() {
  OrientationRecord record;
  record.series = 3;
  record.verdict = "contradicts";
  record.finding = "the header contradicts the anatomy: the face points posterior (+y) in the patient frame";
  record.imbalance = {0.02, -0.83, 0.41};
  record.teeth_cm3 = 4.5;
  record.contradicts_header = true;
  return record;
}

TEST(OrientationRecord, ReadsBackWhatWasWrittenAndRefusesDamage) {
  const Json good = to_json(flagged());
  const OrientationRecord back = read_orientation_record(good, "test");
  EXPECT_EQ(to_json(back), good);
  EXPECT_FALSE(back.trusted());
  for (const char* key :
       {"series", "verdict", "finding", "imbalance", "teeth_cm3", "contradicts_header", "confirmed_at"})
    EXPECT_NE(testing::error_after_damage(
                  good, [&](Json& j) { j.erase(key); }, [](const Json& j) { read_orientation_record(j, "test"); })
                  .find(key),
              std::string::npos)
        << key;
  testing::error_after_damage(
      good, [](Json& j) { j["imbalance"] = "up"; }, [](const Json& j) { read_orientation_record(j, "test"); });
  testing::error_after_damage(
      good, [](Json& j) { j["surprise"] = 1; }, [](const Json& j) { read_orientation_record(j, "test"); });
}

TEST(OrientationRecord, TheNewestRecordOfAContentWinsAndAConfirmationIsTrusted) {
  TemporaryFolder folder;
  testing::write_series(folder / "in", 2, "P1");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, testing::quiet());
  const int64_t case_id = archive.resolve_case("P1");
  EXPECT_FALSE(stored_orientation(archive, case_id, "content-a"));
  EXPECT_EQ(orientation_summary(nullptr), "-");

  store_orientation(archive, case_id, "content-a", flagged());
  ASSERT_TRUE(stored_orientation(archive, case_id, "content-a"));
  EXPECT_FALSE(stored_orientation(archive, case_id, "content-a")->trusted());
  EXPECT_FALSE(stored_orientation(archive, case_id, "content-b"));  // another CT content: not checked
  auto listed = latest_orientations(archive, {case_id});
  EXPECT_EQ(orientation_summary(&listed.at(case_id)), "CONTRADICTS");

  OrientationRecord confirmed = flagged();
  confirmed.confirmed_at = "2026-11-27T10:00:00Z";
  store_orientation(archive, case_id, "content-a", confirmed);
  EXPECT_TRUE(stored_orientation(archive, case_id, "content-a")->trusted());
  listed = latest_orientations(archive, {case_id});
  EXPECT_EQ(orientation_summary(&listed.at(case_id)), "confirmed");
}

}  // namespace
}  // namespace maxillo::records
