// Writers at once (issue 31): importers, each with its own connection as separate processes or
// nodes would have, on the same or on different files. On a PostgreSQL index they run side by
// side (row locks, ON CONFLICT); on SQLite one after another. Either way: one row and one file
// per instance, nothing lost, and a journal whose entries 1..N replay to the index.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "archive/archive.h"
#include "archive/index_journal.h"
#include "archive/object_store.h"
#include "archive_fixture.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

// Runs one importer per input list at once, each with its own archive (connection) and batch
// size; returns their reports.
std::vector<ImportReport> import_at_once(const std::filesystem::path& address,
                                         const std::vector<std::vector<std::filesystem::path>>& inputs,
                                         size_t batch_files) {
  { Archive::open(address, OpenMode::CreateIfMissing); }
  std::vector<ImportReport> reports(inputs.size());
  std::vector<std::thread> importers;
  for (size_t n = 0; n < inputs.size(); ++n)
    importers.emplace_back([&, n] {
      Archive archive = Archive::open(address, OpenMode::CreateIfMissing);
      ImportOptions options = testing::quiet();
      options.batch_files = batch_files + 4 * n;
      reports[n] = archive.import_paths(inputs[n], options);
    });
  for (auto& importer : importers) importer.join();
  return reports;
}

// Series a, b and c of patients P1, P2 and P3 in `folder`.
void write_three_patients(const std::filesystem::path& folder, int slices) {
  testing::write_series(folder / "a", slices, "P1");
  testing::write_series(folder / "b", slices, "P2");
  testing::write_series(folder / "c", slices, "P3");
}

struct Totals {
  size_t imported = 0, already_archived = 0;
};

// The reports added up; none may hold a failure or a conflict.
Totals added_up(const std::vector<ImportReport>& reports) {
  Totals totals;
  for (const auto& report : reports) {
    EXPECT_TRUE(report.all_ok());
    EXPECT_EQ(report.failed + report.conflicts, 0u);
    totals.imported += report.imported;
    totals.already_archived += report.already_archived;
  }
  return totals;
}

struct StoreFiles {
  size_t objects = 0, temporaries = 0;
};

StoreFiles files_in_store(const std::filesystem::path& folder) {
  StoreFiles counted;
  ObjectStore(testing::objects_of(folder)).for_each_file([&](ObjectStore::EntryKind kind, auto&, auto&) {
    (kind == ObjectStore::EntryKind::Object ? counted.objects : counted.temporaries)++;
  });
  return counted;
}

int64_t instances_in(const Archive& archive) {
  int64_t instances = 0;
  for (const auto& s : archive.series()) instances += s.instance_count;
  return instances;
}

TEST(ConcurrentWriters, TheSameInstancesFromTwoImportersAreOneRowAndOneFile) {
  TemporaryFolder folder;
  testing::write_series(folder / "series", 60, "P1");
  for (int round = 0; round < 3; ++round) {  // the race has several outcomes; meet a few of them
    const auto archive_folder = folder / ("archive" + std::to_string(round));
    const auto address = testing::archive_at(archive_folder);
    const Totals totals = added_up(import_at_once(address, {{folder / "series"}, {folder / "series"}}, 7));
    EXPECT_EQ(totals.imported, 60u) << "each instance imported once, whoever won it";
    EXPECT_EQ(totals.already_archived, 60u) << "and found archived by the other importer";
    Archive archive = Archive::open(address);
    EXPECT_EQ(archive.patients().size(), 1u);
    EXPECT_EQ(archive.series().size(), 1u);
    EXPECT_EQ(instances_in(archive), 60);
    const StoreFiles files = files_in_store(archive_folder);
    EXPECT_EQ(files.objects, 60u);
    EXPECT_EQ(files.temporaries, 0u);
    EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  }
}

TEST(ConcurrentWriters, ImportersOfOverlappingSetsMakeNoErrorsAndNoDuplicates) {
  TemporaryFolder folder;
  write_three_patients(folder.path(), 40);
  const auto address = testing::archive_at(folder / "archive");
  // Four importers, every series imported by three of them, in batches of different sizes.
  const Totals totals = added_up(import_at_once(address,
                                                {{folder / "a", folder / "b"},
                                                 {folder / "b", folder / "c"},
                                                 {folder / "c", folder / "a"},
                                                 {folder / "a", folder / "b", folder / "c"}},
                                                5));
  EXPECT_EQ(totals.imported, 120u);          // each instance once
  EXPECT_EQ(totals.already_archived, 240u);  // and recognised by the other two importers of its series
  Archive archive = Archive::open(address);
  EXPECT_EQ(archive.patients().size(), 3u);
  EXPECT_EQ(archive.cases().size(), 3u);
  EXPECT_EQ(archive.series().size(), 3u);
  EXPECT_EQ(instances_in(archive), 120);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

TEST(ConcurrentWriters, DisjointImportsAllLandAndACaseKeepsOnePreoperativeSeries) {
  TemporaryFolder folder;
  testing::write_series(folder / "a", 25, "P1");
  testing::write_series(folder / "b", 25, "P1");  // a second CT series of P1, by another importer
  testing::write_series(folder / "c", 25, "P2");
  testing::write_series(folder / "d", 25, "P3");
  const auto address = testing::archive_at(folder / "archive");
  // P1 and its case exist before (an MR series of P1 came first): the two importers of P1's CT
  // series meet on no new patient row or identity flag, only on the case.
  SeriesMetadata mr = testing::patient_metadata("P1");
  mr.modality = "MR";
  write_ct_series(testing::small_volume(2), mr, folder / "mr");
  Archive::open(address, OpenMode::CreateIfMissing).import_paths({folder / "mr"}, testing::quiet());
  // One batch each: the two transactions on P1's case overlap for as long as possible.
  auto reports = import_at_once(address, {{folder / "a"}, {folder / "b"}, {folder / "c"}, {folder / "d"}}, 50);
  for (const auto& report : reports) {
    EXPECT_TRUE(report.all_ok());
    EXPECT_EQ(report.imported, 25u);
  }
  Archive archive = Archive::open(address);
  EXPECT_EQ(archive.patients().size(), 3u);
  EXPECT_EQ(archive.cases().size(), 3u);
  EXPECT_EQ(instances_in(archive), 102);
  auto contents = archive.case_contents(archive.resolve_case("P1"));
  ASSERT_EQ(contents.series.size(), 3u);
  int preop = 0;
  for (const auto& member : contents.series) preop += member.role == "preop";
  EXPECT_EQ(preop, 1) << "the first CT series attached is preop, the other unassigned";
  EXPECT_EQ(files_in_store(folder / "archive").objects, 102u);
}

TEST(ConcurrentWriters, TheJournalNumbersConcurrentCommitsWithoutGapsAndReplaysToTheIndex) {
  TemporaryFolder folder;
  write_three_patients(folder.path(), 30);
  const auto address = testing::archive_at(folder / "archive");
  // Small batches: many commits from four writers interleave.
  import_at_once(address, {{folder / "a"}, {folder / "b"}, {folder / "c"}, {folder / "a", folder / "b"}}, 3);
  const IndexJournal journal(testing::objects_of(folder / "archive") / "journal");
  const std::vector<int64_t> sequences = journal.sequences();
  ASSERT_FALSE(sequences.empty());
  for (size_t n = 0; n < sequences.size(); ++n) EXPECT_EQ(sequences[n], int64_t(n + 1)) << "no gap, no repeat";
  EXPECT_FALSE(journal.has_pending(sequences.back() + 1)) << "nothing left pending";
  Archive archive = Archive::open(address);
  EXPECT_EQ(instances_in(archive), 90);
  // verify replays every entry in order into a scratch index and compares it row by row.
  const VerifyReport report = archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_TRUE(report.journal_differences.empty()) << report.journal_differences.front();
  EXPECT_TRUE(report.journal_check_failure.empty()) << report.journal_check_failure;
  EXPECT_TRUE(report.consistent());
}

}  // namespace
}  // namespace maxillo
