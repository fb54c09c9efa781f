// The nightly run over the archive: one case's failure, of any kind, never stops the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "archive_fixture.h"
#include "records/case_landmarks.h"
#include "casework/validation/case_validation.h"
#include "nightly/nightly.h"
#include "nightly/nightly_worker.h"
#include "records/plan_archive.h"

namespace maxillo::nightly {
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
  records::store_plan(archive, case_id, planning::distraction_plan(planning::MaxillaryTarget{}, "test"));
  records::attach_landmarks(archive, case_id, {{"S", {0, 0, 0}}, {"N", {0, -70, 10}}}, "test");
  return case_id;
}

TEST(Nightly, ACaseWhoseStoredRecordIsUnreadableFailsAloneWithItsReason) {
  TemporaryFolder folder;
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
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
  record.inputs_hash = casework::validation_inputs_hash(archive, broken, options.validation).value();
  archive.add_artefact(record);

  NightlyReport report = run_nightly(archive, options);
  ASSERT_EQ(report.cases.size(), 2u);
  EXPECT_EQ(report.cases[0].case_id, broken);
  EXPECT_EQ(report.cases[0].outcome, NightlyOutcome::kFailed);
  EXPECT_FALSE(report.cases[0].reason.empty());
  EXPECT_EQ(report.cases[1].case_id, sound);
  EXPECT_EQ(report.cases[1].outcome, NightlyOutcome::kNotValidated);
}

TEST(Nightly, TheScanOfEveryCaseGivesEachTheHashOfItsOwnAndFailsAnUnreadableOneAlone) {
  TemporaryFolder folder;
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  const int64_t first = eligible_case(archive, folder, "P1");
  const int64_t second = eligible_case(archive, folder, "P2");
  const int64_t damaged = eligible_case(archive, folder, "P3");
  testing::write_series(folder / "P4", 3, "P4");  // a CT and nothing else: not eligible
  archive.import_paths({folder / "P4"}, testing::quiet());
  const int64_t bare = archive.resolve_case("P4");
  const casework::ValidationOptions options;
  const auto before = casework::validation_inputs_hash(archive, damaged, options);
  records::attach_landmarks(archive, second, {{"S", {0, 0, 1}}, {"N", {0, -70, 10}}},
                            "test");  // its own, newer landmarks
  // The damaged case's newest landmarks are not a landmark document.
  archive.add_artefact(
      NewArtefact{damaged, "landmarks", archive.store_object("{ damaged"), "application/json", "", "{}"});

  const int64_t missing = bare + 100;
  const auto scan = casework::validation_inputs_hashes(archive, {first, second, damaged, bare, missing}, options);
  ASSERT_EQ(scan.size(), 5u);
  EXPECT_EQ(scan.at(first).hash, casework::validation_inputs_hash(archive, first, options));
  EXPECT_EQ(scan.at(second).hash, casework::validation_inputs_hash(archive, second, options));
  EXPECT_NE(scan.at(first).hash, scan.at(second).hash);  // other landmarks, other inputs
  ASSERT_TRUE(scan.at(first).hash && !scan.at(first).error);
  EXPECT_FALSE(scan.at(bare).hash || scan.at(bare).error);
  EXPECT_EQ(nightly_key(scan.at(bare)), std::nullopt);
  ASSERT_TRUE(scan.at(damaged).error);
  EXPECT_FALSE(scan.at(damaged).hash);
  EXPECT_ANY_THROW(nightly_key(scan.at(damaged)));
  EXPECT_NE(before, std::nullopt);
  ASSERT_TRUE(scan.at(missing).error);
  EXPECT_EQ(nightly_key(scan.at(missing)), std::nullopt);  // no such case: nothing to validate
  EXPECT_EQ(scan.at(first).artefacts.size(), archive.artefacts(first).size());
}

TEST(NightlyWorkers, WorkItemsNameTheCaseAndItsInputsAndParseBack) {
  EXPECT_EQ(nightly_work_item(12, "abc"), "case:12:abc");
  EXPECT_EQ(parse_nightly_work_item("case:12:abc"), std::make_pair(int64_t(12), std::string("abc")));
  EXPECT_EQ(parse_nightly_work_item("case:x:abc"), std::nullopt);
  EXPECT_EQ(parse_nightly_work_item("study:12:abc"), std::nullopt);
}

// Two workers at once share three eligible cases through the work queue. These tiny cases
// cannot be validated (16 x 16 x 3 voxels): each is claimed once, fails once with its reason,
// and is not claimed again, by these workers or by a later one.
TEST(NightlyWorkers, WorkersShareTheCasesAndEachIsFinishedOnce) {
  TemporaryFolder folder;
  const auto address = testing::archive_at(folder / "archive");
  {
    Archive archive = Archive::open(address, OpenMode::CreateIfMissing);
    for (const char* patient : {"P1", "P2", "P3"}) eligible_case(archive, folder, patient);
  }
  NightlyOptions options;
  options.out = folder / "nightly";
  options.claim = true;
  options.lease_seconds = 60;
  options.poll = std::chrono::milliseconds(50);
  std::vector<NightlyReport> reports(2);
  std::vector<std::thread> workers;
  for (size_t w = 0; w < reports.size(); ++w)
    workers.emplace_back([&, w] {
      Archive archive = Archive::open(address);
      NightlyOptions mine = options;
      mine.worker = "worker-" + std::to_string(w);
      reports[w] = run_nightly(archive, mine);
    });
  for (auto& worker : workers) worker.join();
  std::vector<int64_t> seen;
  for (const auto& report : reports)
    for (const auto& c : report.cases) {
      seen.push_back(c.case_id);
      EXPECT_EQ(c.outcome, NightlyOutcome::kFailed);
      EXPECT_FALSE(c.reason.empty());
    }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, (std::vector<int64_t>{1, 2, 3}));  // every case once, by one worker or the other
  Archive archive = Archive::open(address);
  for (const auto& record : WorkQueue(archive, kNightlyQueue).records()) {
    EXPECT_EQ(record.state, "failed") << record.item;
    EXPECT_EQ(record.claims, 1) << record.item;
  }
  options.worker = "later";
  EXPECT_TRUE(run_nightly(archive, options).cases.empty());  // failed cases wait for new inputs
}

// Issue 29, fault 9: the summary after the workers (a Slurm job with afterany) says what they
// left: a case a cancelled worker held, a case nobody claimed, a failed case, each with how to
// finish it, and the batch counts as not done.
TEST(NightlyWorkers, TheSummarySaysWhatTheWorkersLeftAndHowToFinishIt) {
  TemporaryFolder folder;
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  std::vector<int64_t> cases;
  for (const char* patient : {"P1", "P2", "P3", "P4"}) cases.push_back(eligible_case(archive, folder, patient));
  NightlyOptions options;
  options.out = folder / "nightly";
  std::vector<std::string> items;
  for (int64_t id : cases)
    items.push_back(nightly_work_item(id, casework::validation_inputs_hash(archive, id, options.validation).value()));
  WorkQueue queue(archive, kNightlyQueue);
  queue.offer({items[0], items[1], items[2]});  // P4: never offered
  const int64_t now = queue.clock_seconds();
  ASSERT_EQ(queue.claim("cancelled", now - 100, 10), items[0]);  // lease ended
  ASSERT_EQ(queue.claim("failing", now - 95, 600), items[1]);    // items[0] still held then
  ASSERT_TRUE(queue.finish(items[1], "failing", "failed", "no bone found"));

  options.summary_only = true;
  const NightlyReport report = run_nightly(archive, options);
  ASSERT_EQ(report.cases.size(), 4u);
  auto reason_of = [&](size_t n) { return report.cases[n].reason; };
  EXPECT_EQ(report.cases[0].outcome, NightlyOutcome::kNotValidated);
  EXPECT_NE(reason_of(0).find("its worker cancelled stopped before finishing it"), std::string::npos) << reason_of(0);
  EXPECT_EQ(report.cases[1].outcome, NightlyOutcome::kFailed);
  EXPECT_NE(reason_of(1).find("failed on worker failing: no bone found"), std::string::npos) << reason_of(1);
  EXPECT_NE(reason_of(2).find("no worker claimed it"), std::string::npos) << reason_of(2);
  EXPECT_NE(reason_of(3).find("no worker has offered it"), std::string::npos) << reason_of(3);
  for (size_t n : {0u, 2u, 3u}) EXPECT_NE(reason_of(n).find("nightly --claim"), std::string::npos) << reason_of(n);
}

TEST(NightlyWorkers, ACaseUnderALiveLeaseIsBeingValidated) {
  WorkRecord record{"case:1:abc", "pending", "node7:42", "", 1, 1000};
  const NightlyCase held = unfinished_case(1, &record, 990);
  EXPECT_EQ(held.outcome, NightlyOutcome::kNotValidated);
  EXPECT_NE(held.reason.find("being validated by worker node7:42 (lease for 10 s more)"), std::string::npos)
      << held.reason;
}

}  // namespace
}  // namespace maxillo::nightly
