// Verify, repair, export, resolve and artefacts.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include "archive/archive.h"
#include "archive_fixture.h"
#include "core/atomic_file.h"
#include "core/sha256.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

Archive archive_with_series(const TemporaryFolder& folder, WrittenSeries* written = nullptr) {
  auto series = testing::write_series(folder / "in", 4);
  if (written) *written = series;
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  ImportOptions options;
  options.progress = ProgressDisplay::Never;
  archive.import_paths({folder / "in"}, options);
  return archive;
}

TEST(ArchiveVerify, FreshArchiveIsConsistent) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  VerifyReport report = archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_TRUE(report.consistent());
  EXPECT_EQ(report.objects_checked, 4u);
}

TEST(ArchiveVerify, DetectsACorruptedObjectAndRepairDoesNotHideIt) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  auto victim = archive.series_instance_files(1)[2];
  std::filesystem::permissions(victim, std::filesystem::perms::owner_write, std::filesystem::perm_options::add);
  {
    std::fstream file(victim, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(1000);
    file.put('X');
  }
  VerifyReport report = archive.verify(RepairMode::Repair, ProgressDisplay::Never);
  ASSERT_EQ(report.corrupt.size(), 1u);
  EXPECT_EQ(archive.object_path(report.corrupt[0]), victim);
  EXPECT_FALSE(report.data_intact());
  EXPECT_TRUE(std::filesystem::exists(victim));  // evidence is never deleted
}

TEST(ArchiveVerify, MissingObjectIsDataLossAndItsRowsStay) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  auto victim = archive.series_instance_files(1)[0];
  std::filesystem::remove(victim);
  VerifyReport report = archive.verify(RepairMode::Repair, ProgressDisplay::Never);
  EXPECT_EQ(report.missing.size(), 1u);
  EXPECT_EQ(archive.series().front().instance_count, 4);
}

TEST(ArchiveVerify, ReimportingTheOriginalsRestoresALostObject) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  auto victim = archive.series_instance_files(1)[2];
  auto original = read_file(victim);
  std::filesystem::remove(victim);
  ASSERT_EQ(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).missing.size(), 1u);

  ImportOptions options;
  options.progress = ProgressDisplay::Never;
  auto report = archive.import_paths({folder / "in"}, options);
  EXPECT_EQ(report.restored, 1u);
  EXPECT_EQ(report.already_archived, 4u);
  EXPECT_EQ(read_file(victim), original);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

// Issue 29, fault 6: a kill -9 between an object's write and the commit of its rows left an
// object no row names (and sometimes a temporary file), and verify said INCONSISTENT until the
// instance was sent again. Such leftovers are harmless; repair adopts the DICOM object.
TEST(ArchiveVerify, AnInterruptedImportsLeftoversAreHarmlessAndRepairAdoptsTheDicomObject) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  auto unsent = testing::write_series(folder / "unsent", 1, "P9");
  const auto bytes = read_file(unsent.files[0]);
  const auto object = archive.object_path(sha256_hex(bytes));
  std::filesystem::create_directories(object.parent_path());
  write_file_atomically(object, bytes);  // written and synced, its rows never committed
  std::ofstream(object.parent_path() / ".next.tmp-99999-0-1") << "half an object";

  VerifyReport before = archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_EQ(before.orphans.size(), 1u);
  EXPECT_EQ(before.temporaries.size(), 1u);
  EXPECT_TRUE(before.consistent());

  VerifyReport repaired = archive.verify(VerifyOptions{RepairMode::Repair, false, ProgressDisplay::Never, 0});
  ASSERT_EQ(repaired.adopted.size(), 1u);
  EXPECT_EQ(repaired.adopted[0], object);
  EXPECT_EQ(repaired.quarantined, 1u);  // the temporary file
  EXPECT_TRUE(std::filesystem::exists(object));
  EXPECT_NO_THROW(archive.resolve_case("P9"));
  VerifyReport after = archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_TRUE(after.orphans.empty());
  EXPECT_TRUE(after.temporaries.empty());
  EXPECT_TRUE(after.journal_differences.empty());  // the adoption is journalled like an import
  // Sending the instance again finds it archived.
  EXPECT_EQ(archive.import_paths({unsent.files[0]}, testing::quiet()).already_archived, 1u);
}

// Issue 29, fault 5: an object write that failed half-way (a full disk) left its temporary file,
// and verify then said INCONSISTENT for ever. The write is made to fail here by a file-size
// limit in a child process (EFBIG, as ENOSPC would, without mounting a small file system).
TEST(ArchiveVerify, AnObjectWriteThatFailsLeavesNoTemporaryFile) {
  TemporaryFolder folder;
  const auto address = testing::archive_at(folder / "archive");
  { archive_with_series(folder); }
  auto large = write_ct_series(testing::small_volume(1, 256), testing::patient_metadata("P8"), folder / "large");
  const pid_t child = ::fork();
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};  // below one 256 x 256 slice (128 KiB)
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      Archive::open(address).import_paths({large.files[0]}, testing::quiet());
    } catch (const Error& e) {
      ::_exit(e.code() == ErrorCode::kWriteFailed ? 0 : 2);
    }
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the import did not fail with a write error";
  VerifyReport report = Archive::open(address).verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_TRUE(report.temporaries.empty());
  EXPECT_TRUE(report.consistent());
}

TEST(ArchiveVerify, RepairQuarantinesOrphansAndTemporariesAndDeletesNothing) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  std::string orphan_sha = sha256_hex(std::string_view("orphan"));
  auto orphan = archive.object_path(orphan_sha);
  std::filesystem::create_directories(orphan.parent_path());
  std::ofstream(orphan) << "orphan";
  auto temporary = archive.series_instance_files(1)[0].parent_path() / ".abc.tmp-1-2-3";
  std::ofstream(temporary) << "half";
  VerifyReport before = archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never);
  EXPECT_EQ(before.orphans.size(), 1u);
  EXPECT_EQ(before.temporaries.size(), 1u);
  EXPECT_TRUE(before.data_intact());
  EXPECT_TRUE(before.consistent());  // what an interrupted write leaves is no damage
  // No grace period: these strays were made just now (a server archive would leave them).
  VerifyReport repaired = archive.verify(VerifyOptions{RepairMode::Repair, false, ProgressDisplay::Never, 0});
  EXPECT_EQ(repaired.quarantined, 2u);
  EXPECT_FALSE(std::filesystem::exists(orphan));
  EXPECT_FALSE(std::filesystem::exists(temporary));
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  // Set aside, not deleted: both files are in the quarantine until a purge.
  auto quarantine = testing::objects_of(folder / "archive") / "quarantine";
  size_t kept = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(quarantine)) kept += entry.is_regular_file();
  EXPECT_EQ(kept, 2u);
  EXPECT_EQ(archive.purge_quarantine(), 2u);
  EXPECT_FALSE(std::filesystem::exists(quarantine));
}

TEST(ArchiveExport, SeriesComesBackByteIdentical) {
  TemporaryFolder folder;
  WrittenSeries written;
  Archive archive = archive_with_series(folder, &written);
  auto files = archive.export_series(archive.resolve_series(written.series_instance_uid), folder / "out");
  ASSERT_EQ(files.size(), written.files.size());
  for (size_t k = 0; k < files.size(); ++k)
    EXPECT_EQ(testing::read_text(files[k]), testing::read_text(written.files[k]));
  EXPECT_THROW(archive.export_series(999, folder / "out2"), Error);
}

TEST(ArchiveResolve, NumericIdsPatientIdsAndUids) {
  TemporaryFolder folder;
  WrittenSeries written;
  Archive archive = archive_with_series(folder, &written);
  EXPECT_EQ(archive.resolve("P1").kind, ItemKind::Patient);
  EXPECT_EQ(archive.resolve(written.study_instance_uid).kind, ItemKind::Study);
  EXPECT_EQ(archive.resolve(written.series_instance_uid).kind, ItemKind::Series);
  EXPECT_EQ(archive.resolve("1").kind, ItemKind::Series);
  EXPECT_EQ(archive.resolve(archive.instances(1)[3].sop_instance_uid).kind, ItemKind::Instance);
  EXPECT_EQ(archive.instances(1)[3].instance_number, 4);
  try {
    archive.resolve("no-such-thing");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kNotFound);
  }
}

TEST(ArchiveResolve, TypedIdsNameTheirKindEvenWhenBareNumbersCollide) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  // Series 1, study 1, patient 1 and case 1 all exist: the bare "1" is the series.
  EXPECT_EQ(archive.resolve("1").kind, ItemKind::Series);
  for (auto [text, kind] : {std::pair{"case:1", ItemKind::Case},
                            {"patient:1", ItemKind::Patient},
                            {"study:1", ItemKind::Study},
                            {"series:1", ItemKind::Series},
                            {"instance:4", ItemKind::Instance}}) {
    auto item = archive.resolve(text);
    EXPECT_EQ(item.kind, kind) << text;
  }
  EXPECT_EQ(archive.resolve("instance:4").id, 4);
  EXPECT_THROW(archive.resolve("case:99"), Error);
  EXPECT_THROW(archive.resolve("case:x"), Error);
}

TEST(ArchiveArtefacts, LatestMatchingArtefactIsFound) {
  TemporaryFolder folder;
  Archive archive = archive_with_series(folder);
  int64_t case_id = archive.resolve_case("P1");
  std::string first = archive.store_object(std::string_view("%PDF-1.4 first"));
  std::string second = archive.store_object(std::string_view("%PDF-1.4 second"));
  EXPECT_EQ(archive.store_object(std::string_view("%PDF-1.4 first")), first);  // idempotent
  archive.add_artefact({case_id, "report", first, "application/pdf", "inputs-a", R"({"dpi":150})"});
  archive.add_artefact({case_id, "report", second, "application/pdf", "inputs-a", "{}"});
  auto found = archive.find_artefact(case_id, "report", "inputs-a");
  ASSERT_TRUE(found);
  EXPECT_EQ(found->object_sha256, second);
  EXPECT_FALSE(found->program_version.empty());
  EXPECT_FALSE(archive.find_artefact(case_id, "report", "inputs-b"));
  EXPECT_FALSE(archive.find_artefact(case_id, "render", "inputs-a"));
  EXPECT_EQ(archive.artefacts(case_id).size(), 2u);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  EXPECT_THROW(archive.add_artefact({case_id, "report", first, "application/pdf", "x", "not json"}), Error);
}

}  // namespace
}  // namespace maxillo
