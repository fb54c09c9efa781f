// The consultation report filed as a DICOM Encapsulated PDF in the study it analysed, on both
// index engines: the document comes back out byte for byte, it is a "report" series of the case,
// and filing the same report again changes nothing.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "archive_fixture.h"
#include "core/atomic_file.h"
#include "consultation/report_dicom.h"
#include "support/run_command.h"

namespace maxillo::consultation {
namespace {

using testing::TemporaryFolder;

TEST(ReportDicom, TheReportIsFiledInTheAnalysedStudyAndComesBackByteForByte) {
  TemporaryFolder folder;
  testing::write_series(folder / "ct", 3, "P1", "Doe^Jane");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "ct"}, testing::quiet());
  const int64_t case_id = archive.resolve_case("P1");
  const std::string pdf = "%PDF-1.4\n% the consultation report of Doe^Jane\n%%EOF\n";
  write_file_atomically(folder / "report.pdf", pdf);

  const auto filed =
      write_report_dicom(archive, case_id, folder / "report.pdf", folder / "report.dcm", StoreInArchive::Yes);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // the clock must not change the file
  const auto again =
      write_report_dicom(archive, case_id, folder / "report.pdf", folder / "again.dcm", StoreInArchive::Yes);
  EXPECT_EQ(again.sop_instance_uid, filed.sop_instance_uid);
  EXPECT_EQ(read_file(folder / "again.dcm"), read_file(folder / "report.dcm"));

  const auto contents = archive.case_contents(case_id);
  ASSERT_EQ(contents.series.size(), 2u);
  const auto& ct = contents.series[0];
  const auto& report = contents.series[1];
  EXPECT_EQ(report.role, "report");
  EXPECT_EQ(report.series.modality, "DOC");
  EXPECT_EQ(report.series.series_uid, filed.series_instance_uid);
  EXPECT_EQ(report.series.instance_count, 1);  // filed twice, stored once
  EXPECT_EQ(report.series.study, ct.series.study);

  // What the archive hands on is the file written, and DCMTK's own tool takes the PDF back out.
  const auto exported = archive.export_series(report.series.id, folder / "out");
  ASSERT_EQ(exported.size(), 1u);
  EXPECT_EQ(read_file(exported.front()), read_file(folder / "report.dcm"));
  ASSERT_EQ(
      testing::run_command("dcm2pdf " + testing::quote(exported.front()) + " " + testing::quote(folder / "back.pdf"))
          .exit_code,
      0);
  EXPECT_EQ(read_file(folder / "back.pdf"), read_file(folder / "report.pdf"));
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

}  // namespace
}  // namespace maxillo::consultation
