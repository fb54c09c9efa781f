// Losing the index loses nothing: refused when lost, damaged or rolled back; rebuilt from the
// object store and its journal, table for table; repair quarantines instead of deleting.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <fstream>
#include <random>

#include "archive/archive.h"
#include "archive/index_comparison.h"
#include "archive/index_journal.h"
#include "archive_fixture.h"
#include "core/atomic_file.h"
#include "core/sha256.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

using testing::quiet;

RebuildOptions quiet_rebuild(bool force = false) { return RebuildOptions{force, ProgressDisplay::Never}; }

std::filesystem::path index_of(const std::filesystem::path& archive) { return archive / "index.sqlite"; }

void run_sql(const std::filesystem::path& file, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  char* message = nullptr;
  int status = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message);
  EXPECT_EQ(status, SQLITE_OK) << (message ? message : "");
  sqlite3_free(message);
  sqlite3_close(db);
}

size_t files_below(const std::filesystem::path& folder) {
  size_t count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) count += entry.is_regular_file();
  return count;
}

ErrorCode open_error_pointing_to_rebuild(const std::filesystem::path& archive) {
  try {
    Archive::open(archive);
  } catch (const Error& e) {
    EXPECT_NE(e.reason().find("rebuild-index"), std::string::npos) << e.reason();
    return e.code();
  }
  ADD_FAILURE() << "the archive opened";
  return ErrorCode::kProcessing;
}

// An archive whose index holds a row of every table: two patients, a conflict-free second
// series with another name (an identity flag), a changed role, a labelled case, artefacts.
std::filesystem::path archive_with_every_kind_of_row(const TemporaryFolder& folder) {
  testing::write_series(folder / "a", 6, "P1", "Doe^Jane");
  testing::write_series(folder / "b", 4, "P1", "Roe^Richard");
  testing::write_series(folder / "c", 3, "P2", "Müller^Zoë");
  auto path = folder / "archive";
  Archive archive = Archive::open(path, OpenMode::CreateIfMissing);
  archive.import_paths({folder / "a"}, quiet());
  archive.import_paths({folder / "b", folder / "c"}, quiet());
  const int64_t case_id = archive.resolve_case("P1");
  archive.set_series_role(case_id, 2, "postop");
  const int64_t cohort_case = archive.ensure_case("C-7", "cohort:study");
  for (int64_t target : {case_id, cohort_case}) {
    NewArtefact artefact;
    artefact.case_id = target;
    artefact.kind = "report";
    artefact.object_sha256 = archive.store_object("report of case " + std::to_string(target));
    artefact.media_type = "application/pdf";
    artefact.inputs_hash = sha256_hex(std::string_view("inputs"));
    artefact.parameters_json = R"({"pages": 3, "scale": 0.125})";
    archive.add_artefact(artefact);
  }
  return path;
}

// An archive holding one series of `slices` slices of patient P1, written to folder/in.
Archive imported_archive(const TemporaryFolder& folder, int slices) {
  testing::write_series(folder / "in", slices, "P1");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  return archive;
}

// Objects are stored read-only; a test that damages one must first allow writing.
void make_writable(const std::filesystem::path& file) {
  std::filesystem::permissions(file, std::filesystem::perms::owner_write, std::filesystem::perm_options::add);
}

void expect_same_tables(const std::filesystem::path& first, const std::filesystem::path& second) {
  auto differences = compare_index_files(first, second);
  for (const auto& difference : differences) ADD_FAILURE() << difference.describe();
}

TEST(IndexLoss, AMissingEmptyOrDamagedIndexIsRefusedAndNothingIsRecreated) {
  TemporaryFolder folder;
  auto archive = archive_with_every_kind_of_row(folder);
  const size_t objects = files_below(archive / "objects");
  std::filesystem::copy_file(index_of(archive), folder / "original.sqlite");

  std::filesystem::remove(index_of(archive));
  EXPECT_EQ(open_error_pointing_to_rebuild(archive), ErrorCode::kIndexDamaged);
  EXPECT_THROW(Archive::open(archive, OpenMode::CreateIfMissing), Error);  // not even to import
  EXPECT_FALSE(std::filesystem::exists(index_of(archive)));

  std::ofstream(index_of(archive)).close();  // truncated to 0 bytes
  EXPECT_EQ(open_error_pointing_to_rebuild(archive), ErrorCode::kIndexDamaged);

  // 4 KiB of random bytes in the middle of the index.
  std::filesystem::copy_file(folder / "original.sqlite", index_of(archive),
                             std::filesystem::copy_options::overwrite_existing);
  const auto size = std::filesystem::file_size(index_of(archive));
  std::mt19937 random(7);
  std::string noise(4096, '\0');
  for (auto& c : noise) c = char(random());
  {
    std::fstream file(index_of(archive), std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(std::streamoff(size / 2 / 4096 * 4096));
    file.write(noise.data(), std::streamsize(noise.size()));
  }
  EXPECT_EQ(open_error_pointing_to_rebuild(archive), ErrorCode::kIndexDamaged);
  EXPECT_EQ(files_below(archive / "objects"), objects);  // nothing touched
}

TEST(IndexLoss, RebuildFromTheObjectStoreGivesBackEveryTableRowForRow) {
  TemporaryFolder folder;
  auto archive = archive_with_every_kind_of_row(folder);
  std::filesystem::copy_file(index_of(archive), folder / "original.sqlite");
  std::filesystem::remove(index_of(archive));

  RebuildReport report = Archive::rebuild_index(archive, quiet_rebuild());
  EXPECT_TRUE(report.journal_problems.empty());
  EXPECT_TRUE(report.disagreements.empty());
  EXPECT_TRUE(report.unexplained.empty());
  EXPECT_EQ(report.instances_checked, 13u);
  EXPECT_EQ(report.dicom_adopted, 0u);
  EXPECT_EQ(report.rows.at("artefacts"), 2);
  EXPECT_EQ(report.rows.at("identity_flags"), 1);
  expect_same_tables(folder / "original.sqlite", index_of(archive));

  Archive reopened = Archive::open(archive);
  EXPECT_TRUE(reopened.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  // Work goes on where it stopped: a new import continues the journal.
  testing::write_series(folder / "d", 2, "P3");
  EXPECT_EQ(reopened.import_paths({folder / "d"}, quiet()).imported, 2u);
  EXPECT_TRUE(reopened.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

TEST(IndexLoss, ADamagedIndexIsKeptBesideTheRebuiltOne) {
  TemporaryFolder folder;
  auto archive = archive_with_every_kind_of_row(folder);
  std::filesystem::copy_file(index_of(archive), folder / "original.sqlite");
  { std::ofstream(index_of(archive), std::ios::trunc) << "not an index any more"; }
  RebuildReport report = Archive::rebuild_index(archive, quiet_rebuild());
  ASSERT_FALSE(report.previous_index.empty());
  EXPECT_EQ(testing::read_text(report.previous_index), "not an index any more");
  expect_same_tables(folder / "original.sqlite", index_of(archive));
}

TEST(IndexLoss, AnIntactIndexIsRebuiltOnlyWhenForced) {
  TemporaryFolder folder;
  auto archive = archive_with_every_kind_of_row(folder);
  std::filesystem::copy_file(index_of(archive), folder / "original.sqlite");
  try {
    Archive::rebuild_index(archive, quiet_rebuild());
    FAIL() << "an intact index must not be replaced unasked";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kConflict);
  }
  RebuildReport report = Archive::rebuild_index(archive, quiet_rebuild(true));
  EXPECT_TRUE(std::filesystem::exists(report.previous_index));
  expect_same_tables(folder / "original.sqlite", index_of(archive));
}

// An archive whose index was copied after its first import, then imported into `later` times
// more (one journal entry each); the copy is put back in place of the index.
std::filesystem::path archive_with_old_index(const TemporaryFolder& folder, int later) {
  auto path = folder / "archive";
  for (int n = 0; n <= later; ++n) {
    auto series = folder / ("in" + std::to_string(n));
    testing::write_series(series, 2, "P" + std::to_string(n));
    Archive::open(path, OpenMode::CreateIfMissing).import_paths({series}, quiet());  // closed: no WAL left
    if (n == 0) std::filesystem::copy_file(index_of(path), folder / "backup.sqlite");
  }
  std::filesystem::copy_file(index_of(path), folder / "newest.sqlite");
  std::filesystem::copy_file(folder / "backup.sqlite", index_of(path),
                             std::filesystem::copy_options::overwrite_existing);
  return path;
}

// Issue 29, fault 1: an index one commit behind its journal was taken for a killed commit and
// accepted, and the next commit wrote over the journal entry that held the lost import.
TEST(IndexLoss, AnIndexOneCommitBehindItsJournalIsRefusedAndRebuilt) {
  TemporaryFolder folder;
  auto path = archive_with_old_index(folder, 1);
  EXPECT_EQ(open_error_pointing_to_rebuild(path), ErrorCode::kIndexDamaged);
  Archive::rebuild_index(path, quiet_rebuild());
  expect_same_tables(folder / "newest.sqlite", index_of(path));
}

IndexJournal journal_of(const std::filesystem::path& archive) { return IndexJournal(archive / "objects" / "journal"); }

// What a transaction killed between writing its entry and COMMIT leaves: a pending entry one
// past the index's counter. It is no commit, so the archive opens; the next writer keeps it
// aside and writes its own entry of that number.
TEST(IndexLoss, APendingEntryOfAKilledTransactionIsKeptAsideNeverWrittenOver) {
  TemporaryFolder folder;
  auto path = archive_with_old_index(folder, 1);
  const auto journal = journal_of(path);
  std::filesystem::rename(journal.path_of(2), journal.pending_path_of(2));
  const std::string killed = testing::read_text(journal.pending_path_of(2));

  Archive archive = Archive::open(path);
  testing::write_series(folder / "next", 2, "P9");
  EXPECT_EQ(archive.import_paths({folder / "next"}, quiet()).imported, 2u);

  EXPECT_TRUE(journal.has(2));
  EXPECT_FALSE(journal.has_pending(2));
  EXPECT_NE(testing::read_text(journal.path_of(2)), killed);
  std::vector<std::filesystem::path> kept;
  for (const auto& entry : std::filesystem::directory_iterator(journal.folder() / "aborted")) kept.push_back(entry);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(testing::read_text(kept[0]), killed);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).journal_differences.empty());
}

// A writer that died between COMMIT and marking its entry committed: the index's counter
// proves the commit, so the next open marks it, and the journal replays to the same index.
TEST(IndexLoss, AnEntryCommittedButNotYetMarkedIsMarkedAtOpen) {
  TemporaryFolder folder;
  auto path = archive_with_every_kind_of_row(folder);
  const auto journal = journal_of(path);
  const int64_t last = journal.sequences().back();
  std::filesystem::rename(journal.path_of(last), journal.pending_path_of(last));

  Archive archive = Archive::open(path);
  EXPECT_TRUE(journal.has(last));
  EXPECT_FALSE(journal.has_pending(last));
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).journal_differences.empty());
}

// Issue 29, fault 2: `archive rebuild-index --force` swapped a new index in while an import
// that had opened the archive before waited for the store lock; the import then wrote into the
// replaced index and its rows were lost to the archive. A writer follows the swap.
TEST(IndexLoss, AWriterThatWaitedForARebuildWritesIntoTheRebuiltIndex) {
  TemporaryFolder folder;
  auto path = archive_with_every_kind_of_row(folder);
  Archive waiting = Archive::open(path);  // opened before the rebuild, as the racing import was
  const size_t patients_before = waiting.patients().size();
  RebuildReport rebuilt = Archive::rebuild_index(path, quiet_rebuild(true));
  ASSERT_TRUE(std::filesystem::exists(rebuilt.previous_index));

  testing::write_series(folder / "late", 3, "P7");
  EXPECT_EQ(waiting.import_paths({folder / "late"}, quiet()).imported, 3u);

  Archive now = Archive::open(path);
  EXPECT_EQ(now.patients().size(), patients_before + 1);
  auto report = now.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_TRUE(report.orphans.empty());
  EXPECT_TRUE(report.journal_differences.empty());
  EXPECT_TRUE(report.index_intact());
}

TEST(IndexLoss, AnIndexTwoCommitsBehindItsJournalIsRefusedAndRebuilt) {
  TemporaryFolder folder;
  auto path = archive_with_old_index(folder, 2);
  EXPECT_EQ(open_error_pointing_to_rebuild(path), ErrorCode::kIndexDamaged);
  Archive::rebuild_index(path, quiet_rebuild());
  expect_same_tables(folder / "newest.sqlite", index_of(path));
}

TEST(IndexLoss, AnArchiveFromBeforeTheJournalIsSnapshottedAtUpgradeAndRebuildsExactly) {
  TemporaryFolder folder;
  auto archive = archive_with_every_kind_of_row(folder);
  // Make it look like schema version 1: no journal, no index_state.
  std::filesystem::remove_all(archive / "objects" / "journal");
  run_sql(index_of(archive), "DROP TABLE index_state; DROP TABLE work_queue; PRAGMA user_version = 1;");
  { Archive upgraded = Archive::open(archive); }
  std::filesystem::copy_file(index_of(archive), folder / "upgraded.sqlite");
  std::filesystem::remove(index_of(archive));
  RebuildReport report = Archive::rebuild_index(archive, quiet_rebuild());
  EXPECT_EQ(report.journal_entries, 1u);  // the snapshot
  expect_same_tables(folder / "upgraded.sqlite", index_of(archive));
}

TEST(IndexLoss, WithoutAnyJournalTheDicomObjectsAreIndexedFromTheirHeaders) {
  TemporaryFolder folder;
  auto archive = archive_with_every_kind_of_row(folder);
  std::filesystem::remove_all(archive / "objects" / "journal");
  std::filesystem::remove(index_of(archive));
  RebuildReport report = Archive::rebuild_index(archive, quiet_rebuild());
  EXPECT_EQ(report.dicom_adopted, 13u);
  EXPECT_EQ(report.unexplained.size(), 2u);  // the two artefacts' objects: not DICOM, not journalled
  Archive rebuilt = Archive::open(archive);
  EXPECT_EQ(rebuilt.patients().size(), 2u);
  int64_t instances = 0;
  for (const auto& s : rebuilt.series()) instances += s.instance_count;
  EXPECT_EQ(instances, 13);
  // Unexplained objects are orphans, which a repair sets aside (few enough to do so unasked).
  auto verify = rebuilt.verify(RepairMode::Repair, ProgressDisplay::Never);
  EXPECT_EQ(verify.orphans.size(), 2u);
  EXPECT_EQ(verify.quarantined, 2u);
  EXPECT_EQ(files_below(archive / "objects" / "quarantine"), 2u);
}

TEST(IndexLoss, RowsEditedBehindTheArchivesBackAreFoundByVerifyAndRepairRefuses) {
  TemporaryFolder folder;
  auto archive = archive_with_every_kind_of_row(folder);
  run_sql(index_of(archive), "UPDATE patients SET name = 'Someone^Else' WHERE id = 1");
  Archive opened = Archive::open(archive);
  VerifyReport report = opened.verify(RepairMode::Repair, ProgressDisplay::Never);
  EXPECT_FALSE(report.index_intact());
  ASSERT_FALSE(report.journal_differences.empty());
  EXPECT_NE(report.journal_differences[0].find("patients"), std::string::npos) << report.journal_differences[0];
  EXPECT_FALSE(report.repair_refused.empty());
}

TEST(Repair, ManyOrphansStopTheRepairUnlessForcedAndNothingIsEverDeleted) {
  TemporaryFolder folder;
  testing::write_series(folder / "in", 20, "P1");
  testing::write_series(folder / "lost", 12, "P2");
  const auto objects = testing::objects_of(folder / "archive");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  // Twelve objects no row names (as a lost import would leave): 12 of 32 stored.
  for (const auto& file : std::filesystem::directory_iterator(folder / "lost")) {
    auto bytes = read_file(file.path());
    auto target = archive.object_path(sha256_hex(bytes));
    std::filesystem::create_directories(target.parent_path());
    write_file_atomically(target, bytes);
  }
  const size_t stored = files_below(objects);
  VerifyReport refused = archive.verify(RepairMode::Repair, ProgressDisplay::Never);
  EXPECT_EQ(refused.orphans.size(), 12u);
  EXPECT_NE(refused.repair_refused.find("12 of 32"), std::string::npos) << refused.repair_refused;
  EXPECT_EQ(refused.quarantined, 0u);
  EXPECT_EQ(files_below(objects), stored);

  // Forced, the DICOM orphans are adopted (indexed from their headers, as importing them again
  // would): nothing moves and nothing is deleted.
  VerifyReport forced = archive.verify(VerifyOptions{RepairMode::Repair, true, ProgressDisplay::Never, 0});
  EXPECT_EQ(forced.adopted.size(), 12u);
  EXPECT_EQ(forced.quarantined, 0u);
  EXPECT_EQ(files_below(objects), stored + 1);  // the adoption's journal entry
  EXPECT_NO_THROW(archive.resolve_case("P2"));
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

TEST(Repair, AQuarantinedObjectThatARowNamesIsPutBack) {
  TemporaryFolder folder;
  testing::write_series(folder / "in", 30, "P1");
  const auto objects = testing::objects_of(folder / "archive");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  auto victim = archive.series_instance_files(1)[3];
  auto original = read_file(victim);
  // The object went to quarantine (say, a repair while its row was not yet visible).
  std::filesystem::create_directories(objects / "quarantine" / "x");
  std::filesystem::rename(victim, objects / "quarantine" / "x" / sha256_hex(original));
  VerifyReport report = archive.verify(RepairMode::Repair, ProgressDisplay::Never);
  EXPECT_EQ(report.restored.size(), 1u);
  EXPECT_TRUE(report.missing.empty());
  EXPECT_EQ(read_file(victim), original);
}

TEST(Repair, VerifyNamesTheCasesOfABadObject) {
  TemporaryFolder folder;
  Archive archive = imported_archive(folder, 3);
  std::filesystem::remove(archive.series_instance_files(1)[1]);
  VerifyReport report = archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  ASSERT_EQ(report.missing.size(), 1u);
  ASSERT_EQ(report.owners.at(report.missing[0]).size(), 1u);
  EXPECT_EQ(report.owners.at(report.missing[0])[0].rfind("case:1 series:1 instance:", 0), 0u)
      << report.owners.at(report.missing[0])[0];
}

TEST(Healing, ReimportRestoresAnObjectWhoseBytesChanged) {
  TemporaryFolder folder;
  Archive archive = imported_archive(folder, 3);
  auto victim = archive.series_instance_files(1)[2];
  auto original = read_file(victim);
  make_writable(victim);
  {
    std::fstream file(victim, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(700);
    file.put('\x5A');
  }
  ASSERT_EQ(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).corrupt.size(), 1u);
  ImportReport report = archive.import_paths({folder / "in"}, quiet());
  EXPECT_EQ(report.restored, 1u);
  EXPECT_EQ(read_file(victim), original);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).data_intact());
}

TEST(Healing, AWrongFileAlreadyAtAnObjectsNameIsNotTrusted) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 2, "P1");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  auto bytes = read_file(written.files[0]);
  auto target = archive.object_path(sha256_hex(bytes));
  std::filesystem::create_directories(target.parent_path());
  write_file_atomically(target, std::string(bytes.size(), 'x'));  // right size, wrong bytes
  archive.import_paths({folder / "in"}, quiet());
  EXPECT_EQ(read_file(target), bytes);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).data_intact());
}

TEST(ImportBatch, TwoFilesWithOneSopUidInOneImportLeaveNoOrphanAndRaiseNoFlag) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in" / "a", 2, "P1", "Doe^Jane");
  // The same SOP Instance UIDs with another name: conflicts, in the same batch.
  for (const auto& file : written.files) {
    auto bytes = read_file(file);
    std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    auto at = text.find("Doe^Jane");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 8, "Roe^Rick");
    std::filesystem::create_directories(folder / "in" / "b");
    write_file_atomically(folder / "in" / "b" / file.filename(), text);
  }
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  ImportReport report = archive.import_paths({folder / "in"}, quiet());
  EXPECT_EQ(report.imported, 2u);
  EXPECT_EQ(report.conflicts, 2u);
  EXPECT_TRUE(archive.identity_flags().empty());
  VerifyReport verify = archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_TRUE(verify.orphans.empty());
  EXPECT_TRUE(verify.consistent());
}

TEST(Export, AFailedExportLeavesNothingHalfWritten) {
  TemporaryFolder folder;
  Archive archive = imported_archive(folder, 6);
  auto victim = archive.series_instance_files(1)[4];
  make_writable(victim);
  { std::ofstream(victim, std::ios::app) << "appended"; }
  try {
    archive.export_series(1, folder / "out");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kArchiveCorrupt);
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "out"));
  std::filesystem::create_directories(folder / "existing");
  std::ofstream(folder / "existing" / "mine.txt") << "kept";
  EXPECT_THROW(archive.export_series(1, folder / "existing"), Error);
  EXPECT_EQ(files_below(folder / "existing"), 1u);
  for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  // Into an existing folder, once the object is good again.
  archive.import_paths({folder / "in"}, quiet());
  EXPECT_EQ(archive.export_series(1, folder / "existing").size(), 6u);
  EXPECT_EQ(files_below(folder / "existing"), 7u);
}

TEST(OpenModes, AMissingArchiveIsNotCreatedByCommandsThatOnlyRead) {
  TemporaryFolder folder;
  try {
    Archive::open(folder / "nowhere");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kNotFound);
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "nowhere"));
  std::filesystem::create_directories(folder / "empty");
  EXPECT_THROW(Archive::open(folder / "empty"), Error);
  EXPECT_FALSE(std::filesystem::exists(folder / "empty" / "index.sqlite"));
}

}  // namespace
}  // namespace maxillo
