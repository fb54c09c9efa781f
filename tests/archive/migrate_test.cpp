// `archive migrate`: an embedded archive copied into another (on the server run, a PostgreSQL
// index with its shared object folder), verified row by row and hash by hash, idempotent,
// resumable, and never changing its source.
#include <gtest/gtest.h>

#include <algorithm>

#include "archive/archive.h"
#include "archive_fixture.h"
#include "core/atomic_file.h"
#include "core/sha256.h"

namespace maxillo {
namespace {

using testing::quiet;
using testing::TemporaryFolder;

MigrationOptions quiet_migration() { return MigrationOptions{ProgressDisplay::Never}; }

// An embedded archive with a row of every table: two patients, an identity flag, a changed
// role, an image-less labelled case, artefacts.
std::filesystem::path source_archive(const TemporaryFolder& folder) {
  testing::write_series(folder / "a", 6, "P1", "Doe^Jane");
  testing::write_series(folder / "b", 4, "P1", "Roe^Richard");
  testing::write_series(folder / "c", 3, "P2", "Müller^Zoë");
  const auto path = folder / "source";
  Archive archive = Archive::open(path, OpenMode::CreateIfMissing);
  archive.import_paths({folder / "a"}, quiet());
  archive.import_paths({folder / "b", folder / "c"}, quiet());
  const int64_t case_id = archive.resolve_case("P1");
  archive.set_series_role(case_id, 2, "postop");
  NewArtefact artefact;
  artefact.case_id = archive.ensure_case("C-7", "cohort:study");
  artefact.kind = "report";
  artefact.object_sha256 = archive.store_object("a report");
  artefact.media_type = "application/pdf";
  artefact.inputs_hash = sha256_hex(std::string_view("inputs"));
  artefact.parameters_json = R"({"pages": 3, "scale": 0.125})";
  archive.add_artefact(artefact);
  (void)archive.deidentification_secret();
  return path;
}

std::string digest_of_folder(const std::filesystem::path& folder) {
  std::vector<std::string> entries;
  // Every file, the index's -wal and -shm included: a plain read-only SQLite connection made
  // them in the source (issue 29, fault 10).
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) entries.push_back(entry.path().string() + " " + sha256_hex(read_file(entry.path())));
  std::sort(entries.begin(), entries.end());
  std::string all;
  for (const auto& e : entries) all += e + "\n";
  return sha256_hex(all);
}

size_t files_below(const std::filesystem::path& folder) {
  size_t count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) count += entry.is_regular_file();
  return count;
}

TEST(Migrate, EveryRowAndObjectArrivesVerifiedAndTheSourceIsUntouched) {
  TemporaryFolder folder;
  const auto source = source_archive(folder);
  const auto before = digest_of_folder(source);
  const auto target = testing::archive_at(folder / "target");

  MigrationReport report = Archive::migrate(source, target, quiet_migration());
  EXPECT_TRUE(report.verified()) << (report.differences.empty() ? "" : report.differences[0]);
  EXPECT_EQ(report.objects_copied, 14u);  // 13 instances and the report
  EXPECT_EQ(report.rows.at("instances"), 13);
  EXPECT_EQ(report.rows.at("identity_flags"), 1);
  EXPECT_EQ(digest_of_folder(source), before);

  Archive migrated = Archive::open(target);
  Archive original = Archive::open(source);
  EXPECT_EQ(migrated.patients().size(), 3u);  // P1, P2 and the image-less C-7
  EXPECT_EQ(migrated.case_contents(1).series.size(), original.case_contents(1).series.size());
  EXPECT_EQ(migrated.artefacts(3).size(), 1u);
  EXPECT_EQ(migrated.deidentification_secret(), original.deidentification_secret());
  EXPECT_TRUE(migrated.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  // Work goes on in the target: new rows take new ids, and it still verifies.
  testing::write_series(folder / "d", 2, "P3");
  EXPECT_EQ(migrated.import_paths({folder / "d"}, quiet()).imported, 2u);
  EXPECT_EQ(migrated.patients().size(), 4u);
  EXPECT_TRUE(migrated.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

TEST(Migrate, ARepeatedRunCopiesNothingAndAnInterruptedOneIsCompleted) {
  TemporaryFolder folder;
  const auto source = source_archive(folder);
  const auto target = testing::archive_at(folder / "target");
  ASSERT_TRUE(Archive::migrate(source, target, quiet_migration()).verified());

  MigrationReport again = Archive::migrate(source, target, quiet_migration());
  EXPECT_TRUE(again.verified());
  EXPECT_EQ(again.objects_copied, 0u);
  EXPECT_EQ(again.objects_present, 14u);

  // What a kill part-way leaves: objects and journal entries not yet copied.
  const auto objects = testing::objects_of(folder / "target");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(objects))
    if (entry.is_regular_file() && entry.path().parent_path().filename() != "settings") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 5u);
  for (size_t n = 0; n < 5; ++n) std::filesystem::remove(files[n * files.size() / 5]);
  const size_t stored = files_below(objects);
  // A migration killed after its first step leaves an archive that holds less than its source:
  // every command but the migration refuses it, saying so (issue 29, fault 10).
  const auto settings = objects / "settings";
  std::filesystem::create_directories(settings);
  std::ofstream(settings / "migration-in-progress") << source.string() << "\n2026-11-27T10:00:00Z\n";
  try {
    Archive::open(target);
    ADD_FAILURE() << "a half-migrated archive opened";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kConflict);
    EXPECT_NE(std::string(e.what()).find("has not finished"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(source.string()), std::string::npos) << e.what();
  }
  MigrationReport resumed = Archive::migrate(source, target, quiet_migration());
  EXPECT_TRUE(resumed.verified());
  EXPECT_EQ(files_below(objects), stored + 5);
  EXPECT_TRUE(Archive::open(target).verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

TEST(Migrate, ATargetWithAHistoryOfItsOwnIsRefused) {
  TemporaryFolder folder;
  const auto source = source_archive(folder);
  const auto target = testing::archive_at(folder / "target");
  testing::write_series(folder / "other", 2, "OTHER");
  Archive::open(target, OpenMode::CreateIfMissing).import_paths({folder / "other"}, quiet());
  try {
    Archive::migrate(source, target, quiet_migration());
    FAIL() << "migrated over another archive";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kConflict);
  }
  EXPECT_EQ(Archive::open(target).patients().size(), 1u);
}

}  // namespace
}  // namespace maxillo
