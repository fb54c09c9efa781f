// The real cadaver head CT (../shared/data/cthead-stanford) through the whole pipe, as a clinic
// would run it: wrap as DICOM, import, report. Skipped where the data is absent.
#include <gtest/gtest.h>

#include "support/cadaver_dicom.h"
#include "support/pdf_tools.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

TEST(CadaverReport, WrapImportAndReport) {
  if (!testing::cadaver_present())
    GTEST_SKIP() << "real data absent: " << testing::cadaver_data() << " (see ../shared/data/README.md)";
  testing::TemporaryFolder folder("maxillo-cadaver");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder / "archive");

  const auto wrap = testing::wrap_cadaver_as_dicom(folder / "ct");
  ASSERT_EQ(wrap.exit_code, 0) << wrap.output;
  auto import = run_command(maxillo + " import " + quote(folder / "ct") + " 2>&1");
  ASSERT_EQ(import.exit_code, 0) << import.output;
  EXPECT_NE(import.output.find("113 imported"), std::string::npos) << import.output;

  auto report = run_command(maxillo + " report CTHEAD-UNC --out " + quote(folder / "report.pdf") + " 2>&1");
  ASSERT_EQ(report.exit_code, 0) << report.output;
  EXPECT_EQ(run_command("qpdf --check " + quote(folder / "report.pdf") + " >/dev/null 2>&1").exit_code, 0);
  auto text = testing::pdf_text(folder / "report.pdf");
  EXPECT_NE(text.find("CThead"), std::string::npos);
  // No landmark file: the landmarks are found on the CT and stored, and the report says so.
  EXPECT_NE(text.find("found automatically"), std::string::npos) << text.substr(0, 2000);
  EXPECT_NE(text.find("SNA"), std::string::npos) << "the cephalometry of the automatic landmarks";
  auto views = testing::pdf_images(folder / "report.pdf", folder / "images");
  ASSERT_EQ(views.size(), 9u) << "three views of skin and of bone, and the landmarks drawn in three views";
  for (const auto& view : views) EXPECT_GT(view.foreground_fraction, 0.1) << view.file;
  // The landmark page: each landmark drawn and labelled, the views named by what they show.
  EXPECT_NE(text.find("right lateral: midline and right-sided landmarks"), std::string::npos);
  EXPECT_NE(text.find("left lateral: left-sided landmarks"), std::string::npos);

  // A second report reuses the stored surfaces and renders (same derivation keys).
  auto again = run_command(maxillo + " --json report CTHEAD-UNC --out " + quote(folder / "again.pdf") + " 2>/dev/null");
  ASSERT_EQ(again.exit_code, 0);
  EXPECT_NE(again.output.find("\"surfaces_reused\": true"), std::string::npos) << again.output;
  // ... and the landmark pictures: still three of them in the archive.
  auto show = run_command(maxillo + " --json show case:1 2>/dev/null");
  EXPECT_EQ(testing::count_of(show.output, "\"landmark-render\""), 3u) << show.output;
}

}  // namespace
}  // namespace maxillo
