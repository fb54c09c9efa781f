// The nightly run over the archive: one case's failure, of any kind, never stops the others.
#include <gtest/gtest.h>

#include "archive_fixture.h"
#include "pipeline/case_landmarks.h"
#include "pipeline/case_validation.h"
#include "pipeline/nightly.h"
#include "pipeline/plan_archive.h"

namespace maxillo::pipeline {
namespace {

using testing::TemporaryFolder;

// A patient with a pre- and a post-operative CT, a plan and landmarks: eligible for validation.
int64_t eligible_case(Archive& archive, const TemporaryFolder& folder, const std::string& patient_id) {
  testing::write_series(folder / patient_id / "pre", 3, patient_id);
  auto metadata = testing::patient_metadata(patient_id);
  metadata.study_date = "20250101";
  write_ct_series(testing::small_volume(3, 16, 7), metadata, folder / patient_id / "post");
  archive.import_paths({folder / patient_id}, testing::quiet());
  const int64_t case_id = archive.resolve_case(patient_id);
  for (const auto& member : archive.case_contents(case_id).series)
    if (member.role != "preop") archive.set_series_role(case_id, member.series.id, "postop");
  store_plan(archive, case_id, planning::distraction_plan(planning::MaxillaryTarget{}, "test"));
  attach_landmarks(archive, case_id, {{"S", {0, 0, 0}}, {"N", {0, -70, 10}}}, "test");
  return case_id;
}

TEST(Nightly, ACaseWhoseStoredRecordIsUnreadableFailsAloneWithItsReason) {
  TemporaryFolder folder;
  Archive archive = Archive::open(folder / "archive", OpenMode::CreateIfMissing);
  const int64_t broken = eligible_case(archive, folder, "P1");
  const int64_t sound = eligible_case(archive, folder, "P2");
  // A validation record of the broken case that is not JSON at all (a damaged artefact).
  NightlyOptions options;
  options.out = folder / "nightly";
  options.summary_only = true;
  NewArtefact record;
  record.case_id = broken;
  record.kind = "validation";
  record.object_sha256 = archive.store_object("{ this is not JSON");
  record.media_type = "application/json";
  record.inputs_hash = validation_inputs_hash(archive, broken, options.validation).value();
  archive.add_artefact(record);

  NightlyReport report = run_nightly(archive, options);
  ASSERT_EQ(report.cases.size(), 2u);
  EXPECT_EQ(report.cases[0].case_id, broken);
  EXPECT_EQ(report.cases[0].outcome, NightlyOutcome::kFailed);
  EXPECT_FALSE(report.cases[0].reason.empty());
  EXPECT_EQ(report.cases[1].case_id, sound);
  EXPECT_EQ(report.cases[1].outcome, NightlyOutcome::kNotValidated);
}

}  // namespace
}  // namespace maxillo::pipeline
