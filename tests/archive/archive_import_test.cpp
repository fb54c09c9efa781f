// Importing: idempotence, conflicts, identity flags, every kind of bad input (concurrent
// importers: concurrent_writers_test.cpp).
#include <gtest/gtest.h>

#include <vector>

#include "archive/archive.h"
#include "archive_fixture.h"
#include "core/utf8.h"
#include "support/bad_dicom_files.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

using testing::quiet;

const std::filesystem::path kBadInputs = std::filesystem::path(MAXILLO_SOURCE_DIR) / "tests/data/bad-inputs";

TEST(ArchiveImport, IndexesPatientStudySeriesAndInstances) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 5, "P1", "Müller-Łukasz^Zoë");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  ImportReport report = archive.import_paths({folder / "in"}, quiet());
  EXPECT_EQ(report.imported, 5u);
  EXPECT_TRUE(report.all_ok());

  auto patients = archive.patients();
  ASSERT_EQ(patients.size(), 1u);
  EXPECT_EQ(patients[0].patient_id, "P1");
  EXPECT_EQ(patients[0].name, "Müller-Łukasz^Zoë");
  EXPECT_EQ(patients[0].birth_date, "19800101");
  auto studies = archive.studies(patients[0].id);
  ASSERT_EQ(studies.size(), 1u);
  EXPECT_EQ(studies[0].study_uid, written.study_instance_uid);
  EXPECT_EQ(studies[0].date, "20240315");
  auto series = archive.series(studies[0].id);
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series[0].series_uid, written.series_instance_uid);
  EXPECT_EQ(series[0].modality, "CT");
  EXPECT_EQ(series[0].instance_count, 5);
  EXPECT_EQ(series[0].rows, 16);
  EXPECT_DOUBLE_EQ(series[0].pixel_spacing_row.value(), 0.5);
  EXPECT_DOUBLE_EQ(series[0].slice_thickness.value(), 1.0);

  auto files = archive.series_instance_files(series[0].id);
  ASSERT_EQ(files.size(), 5u);
  for (size_t k = 0; k < files.size(); ++k)
    EXPECT_EQ(testing::read_text(files[k]), testing::read_text(written.files[k])) << k;  // ordered by instance number

  // A default case attached the CT series as pre-operative.
  auto case_id = archive.resolve_case("P1");
  auto contents = archive.case_contents(case_id);
  EXPECT_EQ(contents.record.label, "default");
  EXPECT_EQ(contents.patient.patient_id, "P1");
  ASSERT_EQ(contents.series.size(), 1u);
  EXPECT_EQ(contents.series[0].role, "preop");
}

TEST(ArchiveImport, SecondCtSeriesOfAPatientIsUnassigned) {
  TemporaryFolder folder;
  testing::write_series(folder / "a", 2, "P1");
  testing::write_series(folder / "b", 2, "P1");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "a"}, quiet());
  archive.import_paths({folder / "b"}, quiet());
  auto contents = archive.case_contents(archive.resolve_case("P1"));
  ASSERT_EQ(contents.series.size(), 2u);
  int preop = 0, unassigned = 0;
  for (const auto& member : contents.series) (member.role == "preop" ? preop : unassigned)++;
  EXPECT_EQ(preop, 1);
  EXPECT_EQ(unassigned, 1);
  EXPECT_EQ(archive.cases().size(), 1u);
}

TEST(ArchiveImport, ReimportChangesNothingAndSaysSo) {
  TemporaryFolder folder;
  testing::write_series(folder / "in", 4);
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  ImportReport again = archive.import_paths({folder / "in"}, quiet());
  EXPECT_EQ(again.imported, 0u);
  EXPECT_EQ(again.already_archived, 4u);
  EXPECT_TRUE(again.all_ok());
  EXPECT_EQ(archive.series().front().instance_count, 4);
  // Also through a second path to the same file inside one import (same bytes, same UID).
  ImportReport twice = archive.import_paths({folder / "in", folder / "in"}, quiet());
  EXPECT_EQ(twice.already_archived, 8u);
}

TEST(ArchiveImport, SameSopInstanceUidWithOtherBytesIsAConflictAndTheOriginalIsKept) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 2);
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  auto original = testing::read_text(archive.series_instance_files(1)[0]);

  // Same SOP Instance UID, different pixels: rewrite slice 0 with another study description.
  DcmFileFormat file;
  file.loadFile(written.files[0].c_str());
  file.getDataset()->putAndInsertString(DCM_StudyDescription, "changed");
  std::filesystem::create_directories(folder / "changed");
  file.saveFile((folder / "changed" / "x.dcm").c_str(), EXS_LittleEndianExplicit);

  std::vector<ImportProblem> seen;
  ImportOptions options = quiet();
  options.on_problem = [&](const ImportProblem& p) { seen.push_back(p); };
  ImportReport report = archive.import_paths({folder / "changed"}, options);
  EXPECT_EQ(report.conflicts, 1u);
  EXPECT_EQ(report.imported, 0u);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].outcome, ImportOutcome::Conflict);
  EXPECT_EQ(seen[0].path, folder / "changed" / "x.dcm");
  EXPECT_NE(seen[0].reason.find("SOP Instance UID"), std::string::npos);
  EXPECT_EQ(testing::read_text(archive.series_instance_files(1)[0]), original);
  EXPECT_EQ(archive.series().front().instance_count, 2);
}

TEST(ArchiveImport, PatientIdWithAnotherNameIsFlaggedNotMerged) {
  TemporaryFolder folder;
  testing::write_series(folder / "a", 3, "P7", "Doe^Jane");
  testing::write_series(folder / "b", 3, "P7", "Roe^Richard");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "a"}, quiet());
  ImportReport report = archive.import_paths({folder / "b"}, quiet());
  EXPECT_EQ(report.imported, 3u);
  EXPECT_EQ(report.identity_flags, 1u);  // one flag, not one per slice
  auto flags = archive.identity_flags();
  ASSERT_EQ(flags.size(), 1u);
  EXPECT_EQ(flags[0].attribute, "name");
  EXPECT_EQ(flags[0].archived_value, "Doe^Jane");
  EXPECT_EQ(flags[0].arrived_value, "Roe^Richard");
  EXPECT_NE(flags[0].source_path.find("/b/"), std::string::npos);
  ASSERT_EQ(archive.patients().size(), 1u);
  EXPECT_EQ(archive.patients()[0].name, "Doe^Jane");  // the archived identity is not overwritten
}

TEST(ArchiveImport, EveryBadInputIsNamedWithItsReasonWhileTheRestImports) {
  TemporaryFolder folder;
  auto good = testing::write_series(folder / "in" / "good", 3);
  auto spare = testing::write_series(folder / "spare", 3, "P2");
  auto bad = folder / "in" / "bad";
  std::filesystem::create_directories(bad);
  std::ofstream(bad / "notes.txt") << "this is not DICOM, just text long enough to be read as a file ........"
                                   << std::string(200, '.');
  testing::write_truncated(spare.files[0], bad / "truncated.dcm", 0.6);
  testing::write_without(spare.files[1], DCM_SOPInstanceUID, bad / "no_sop_uid.dcm");
  testing::write_jpeg2000(spare.files[2], bad / "jpeg2000.dcm");
  std::filesystem::create_symlink(folder / "nowhere.dcm", bad / "dangling.dcm");

  std::vector<ImportProblem> seen;
  ImportOptions options = quiet();
  options.on_problem = [&](const ImportProblem& p) { seen.push_back(p); };
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  ImportReport report = archive.import_paths({folder / "in", folder / "missing-folder"}, options);
  EXPECT_EQ(report.imported, 3u);
  EXPECT_EQ(report.failed, 6u);
  EXPECT_FALSE(report.all_ok());
  std::map<std::string, ImportProblem> by_name;
  for (const auto& p : seen) by_name[p.path.filename().string()] = p;
  ASSERT_EQ(by_name.size(), 6u);
  EXPECT_EQ(by_name["notes.txt"].code, ErrorCode::kNotDicom);
  EXPECT_EQ(by_name["truncated.dcm"].code, ErrorCode::kTruncated) << by_name["truncated.dcm"].reason;
  EXPECT_EQ(by_name["no_sop_uid.dcm"].code, ErrorCode::kMissingAttribute);
  EXPECT_NE(by_name["no_sop_uid.dcm"].reason.find("SOP Instance UID"), std::string::npos);
  EXPECT_EQ(by_name["jpeg2000.dcm"].code, ErrorCode::kUnsupportedSyntax) << by_name["jpeg2000.dcm"].reason;
  EXPECT_NE(by_name["jpeg2000.dcm"].reason.find("1.2.840.10008.1.2.4.90"), std::string::npos);
  EXPECT_EQ(by_name["dangling.dcm"].code, ErrorCode::kFileNotFound);
  EXPECT_NE(by_name["dangling.dcm"].reason.find("unreadable"), std::string::npos);
  EXPECT_EQ(by_name["missing-folder"].code, ErrorCode::kFileNotFound);
  for (const auto& p : seen) EXPECT_FALSE(p.reason.empty());
  EXPECT_EQ(archive.series().size(), 1u);
}

// The files that broke the import (tests/data/bad-inputs, refused one by one by the structure
// walk: tests/dicom/dicom_structure_test.cpp) among good ones: each refused, the rest imported.
TEST(DicomStructure, OneBadFileNeverEndsTheBatch) {
  TemporaryFolder folder;
  testing::write_series(folder / "in" / "good", 3);
  for (const auto& bad : std::filesystem::directory_iterator(kBadInputs))
    if (bad.path().extension() == ".dcm") std::filesystem::copy_file(bad.path(), folder / "in" / bad.path().filename());
  {  // 100 GiB of (sparse) nothing named like a DICOM file: refused unread, not std::bad_alloc
    std::ofstream(folder / "in" / "huge.dcm").close();
    std::filesystem::resize_file(folder / "in" / "huge.dcm", uintmax_t(100) << 30);
  }
  Archive archive = Archive::open(folder / "archive", OpenMode::CreateIfMissing);
  ImportOptions options;
  options.progress = ProgressDisplay::Never;
  ImportReport report = archive.import_paths({folder / "in"}, options);
  EXPECT_EQ(report.imported, 3u);
  EXPECT_EQ(report.failed, 4u);
  for (const auto& problem : report.problems) {
    EXPECT_TRUE(is_valid_utf8(problem.reason)) << problem.reason;
    if (problem.path.filename() == "huge.dcm") {
      EXPECT_EQ(problem.code, ErrorCode::kBadValue);
      EXPECT_NE(problem.reason.find("100.0 GiB"), std::string::npos) << problem.reason;
    }
  }
}

// Issue 29, fault 8: a folder holding only a symbolic link to a series imported nothing and
// said nothing. Links to folders are followed; a link back up the tree is listed once.
TEST(ArchiveImport, ASymbolicLinkToASeriesFolderIsFollowedAndALoopIsListedOnce) {
  TemporaryFolder folder;
  testing::write_series(folder / "elsewhere" / "series", 3);
  std::filesystem::create_directories(folder / "in");
  std::filesystem::create_directory_symlink(folder / "elsewhere" / "series", folder / "in" / "series");
  std::filesystem::create_directory_symlink(folder / "in", folder / "in" / "loop");
  std::filesystem::create_directory_symlink(folder / "elsewhere" / "series", folder / "in" / "same-again");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  ImportReport report = archive.import_paths({folder / "in"}, quiet());
  EXPECT_EQ(report.imported, 3u);
  EXPECT_EQ(report.files(), 3u);  // each file once, though two links lead to it and one loops
  EXPECT_TRUE(report.all_ok());
}

TEST(ArchiveImport, TruncationAnywhereInThePixelsOrHeaderIsDetected) {
  TemporaryFolder folder;
  auto spare = testing::write_series(folder / "spare", 1);
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  for (double fraction : {0.2, 0.5, 0.9, 0.999}) {
    auto path = folder / ("cut" + std::to_string(int(fraction * 1000)) + ".dcm");
    testing::write_truncated(spare.files[0], path, fraction);
    ImportReport report = archive.import_paths({path}, quiet());
    ASSERT_EQ(report.failed, 1u) << fraction;
    EXPECT_EQ(report.problems[0].code, ErrorCode::kTruncated) << fraction << " " << report.problems[0].reason;
  }
}

}  // namespace
}  // namespace maxillo
