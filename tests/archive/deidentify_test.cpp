// De-identified exports: no identity left, pseudonyms stable within an archive and unlinkable
// across archives, pixels untouched, and the copies import as a new (pseudonymous) patient.
#include <gtest/gtest.h>

#include <regex>

#include "archive/archive.h"
#include "archive/dicom_deidentify.h"
#include "archive/dicom_slice_reader.h"
#include "archive_fixture.h"

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

TEST(Deidentify, PseudonymousUidsAreValidDeterministicAndKeyed) {
  std::regex uid_form("2\\.25\\.[1-9][0-9]*");
  auto uid = pseudonymous_uid("secret", "1.2.3.4");
  EXPECT_TRUE(std::regex_match(uid, uid_form)) << uid;
  EXPECT_LE(uid.size(), 64u);
  EXPECT_EQ(uid, pseudonymous_uid("secret", "1.2.3.4"));
  EXPECT_NE(uid, pseudonymous_uid("other secret", "1.2.3.4"));
  EXPECT_NE(uid, pseudonymous_uid("secret", "1.2.3.5"));
  EXPECT_EQ(pseudonym_for("secret", "P1").size(), 17u);
  EXPECT_NE(pseudonym_for("secret", "P1"), pseudonym_for("secret", "P2"));
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
  EXPECT_EQ(patient.sex, "F");  // patient characteristics retained
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

}  // namespace
}  // namespace maxillo
