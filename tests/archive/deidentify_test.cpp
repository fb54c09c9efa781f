// De-identified exports: no identity left, pseudonyms stable within an archive and unlinkable
// across archives, pixels untouched, and the copies import as a new (pseudonymous) patient.
#include <gtest/gtest.h>

#include <dcmtk/dcmdata/dctk.h>

#include <span>

#include "archive/archive.h"
#include "archive_fixture.h"
#include "dicom/dicom_deidentify.h"
#include "dicom/dicom_encapsulated_pdf.h"
#include "dicom/dicom_slice_reader.h"

namespace maxillo {
namespace {
using testing::TemporaryFolder;

Archive archive_of(const TemporaryFolder& folder, const std::string& name, const std::filesystem::path& input) {
  Archive archive = Archive::open(testing::archive_at(folder / name), OpenMode::CreateIfMissing);
  ImportOptions quiet;
  quiet.progress = ProgressDisplay::Never;
  archive.import_paths({input}, quiet);
  return archive;
}

TEST(Deidentify, ExportedCopiesCarryNoIdentityAndImportAsAPseudonymousPatient) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 4, "P1", "Doe^Jane");
  Archive archive = archive_of(folder, "archive", folder / "in");
  auto series = archive.resolve_series(written.series_instance_uid);
  auto files = archive.export_series(series, folder / "out", ExportProfile::Deidentified);
  ASSERT_EQ(files.size(), 4u);

  for (size_t k = 0; k < files.size(); ++k) {
    auto text = testing::read_text(files[k]);
    EXPECT_EQ(text.find("Doe^Jane"), std::string::npos);
    EXPECT_EQ(text.find("19800101"), std::string::npos) << "birth date left in " << files[k];
    EXPECT_EQ(text.find(written.series_instance_uid), std::string::npos);
    auto copy = read_dicom_slice(files[k]);
    auto original = read_dicom_slice(written.files[k]);
    EXPECT_EQ(copy.hu, original.hu) << "pixels must be untouched";
  }

  Archive research = archive_of(folder, "research", folder / "out");
  ASSERT_EQ(research.patients().size(), 1u);
  auto patient = research.patients().front();
  EXPECT_EQ(patient.patient_id, pseudonym_for(archive.deidentification_secret(), "P1"));
  EXPECT_EQ(patient.name, patient.patient_id);
  EXPECT_EQ(patient.birth_date, "");
  EXPECT_EQ(patient.sex, "F");                             // patient characteristics retained
  EXPECT_EQ(research.studies().front().date, "20240315");  // longitudinal dates retained
  EXPECT_EQ(research.series().front().instance_count, 4);
}

TEST(Deidentify, SameArchiveSamePseudonymsOtherArchiveOthers) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 2);
  Archive first = archive_of(folder, "first", folder / "in");
  Archive second = archive_of(folder, "second", folder / "in");
  auto a = first.export_series(1, folder / "a", ExportProfile::Deidentified);
  auto b = first.export_series(1, folder / "b", ExportProfile::Deidentified);
  auto c = second.export_series(1, folder / "c", ExportProfile::Deidentified);
  EXPECT_EQ(a[0].filename(), b[0].filename());  // the file name holds the new SOP Instance UID
  EXPECT_EQ(testing::read_text(a[0]), testing::read_text(b[0]));
  EXPECT_NE(a[0].filename(), c[0].filename());
  EXPECT_NE(first.deidentification_secret(), second.deidentification_secret());
}

// A report filed as an Encapsulated PDF names the patient inside the document, where the
// profile cannot reach: it never leaves de-identified, nothing of it is written, and the archived
// original still exports as it is.
TEST(Deidentify, AnEncapsulatedReportIsRefusedAndNothingOfItIsWritten) {
  TemporaryFolder folder;
  testing::write_series(folder / "ct", 2, "P1", "Doe^Jane");
  Archive archive = archive_of(folder, "archive", folder / "ct");
  const auto contents = archive.case_contents(archive.resolve_case("P1"));
  const std::string pdf = "%PDF-1.4\n% Consultation report of Doe^Jane\n%%EOF\n";
  std::filesystem::create_directories(folder / "report");
  write_encapsulated_pdf(std::as_bytes(std::span(pdf)),
                         EncapsulatedReport{contents.patient, contents.studies.front(), "Report"},
                         folder / "report" / "report.dcm");
  ImportOptions quiet;
  quiet.progress = ProgressDisplay::Never;
  ASSERT_TRUE(archive.import_paths({folder / "report"}, quiet).all_ok());
  int64_t report = 0;
  for (const auto& s : archive.series())
    if (s.modality == "DOC") report = s.id;
  ASSERT_NE(report, 0);

  try {
    archive.export_series(report, folder / "out", ExportProfile::Deidentified);
    FAIL() << "an encapsulated PDF was exported as de-identified";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kCannotDeidentify);
    EXPECT_EQ(e.subject(), "series:" + std::to_string(report));
    EXPECT_NE(e.reason().find("application/pdf"), std::string::npos) << e.reason();
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "out"));
  const auto original = archive.export_series(report, folder / "original", ExportProfile::Original);
  ASSERT_EQ(original.size(), 1u);
  EXPECT_NE(testing::read_text(original.front()).find("Doe^Jane"), std::string::npos);
}

// A file that declares burnt-in text (Burned In Annotation YES) is refused the same way.
TEST(Deidentify, PixelsDeclaredToCarryBurntInTextAreRefused) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "ct", 2, "P1", "Doe^Jane");
  for (const auto& file : written.files) {
    DcmFileFormat dicom;
    ASSERT_TRUE(dicom.loadFile(file.c_str()).good());
    dicom.getDataset()->putAndInsertString(DCM_BurnedInAnnotation, "YES");
    ASSERT_TRUE(dicom.saveFile(file.c_str()).good());
  }
  Archive archive = archive_of(folder, "archive", folder / "ct");
  const auto series = archive.resolve_series(written.series_instance_uid);
  try {
    archive.export_series(series, folder / "out", ExportProfile::Deidentified);
    FAIL() << "burnt-in text was exported as de-identified";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kCannotDeidentify);
    EXPECT_NE(e.reason().find("Burned In Annotation"), std::string::npos) << e.reason();
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "out"));
}

}  // namespace
}  // namespace maxillo
