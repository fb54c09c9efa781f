// Black-box test of the main job: `maxillo demo` from nothing to a PDF report, checked with the
// real poppler and qpdf tools, and the report's images checked for content.
#include <gtest/gtest.h>

#include "core/json.h"
#include "support/pdf_tools.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

class DemoTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    folder_ = new testing::TemporaryFolder("maxillo-demo");
    demo_ = run_command(std::string(MAXILLO_BINARY) + " demo --out " + quote(folder_->path() / "out") + " 2>&1");
  }
  static void TearDownTestSuite() { delete folder_; }
  static std::filesystem::path report() { return folder_->path() / "out" / "report.pdf"; }

  static inline testing::TemporaryFolder* folder_ = nullptr;
  static inline testing::CommandResult demo_;
};

TEST_F(DemoTest, RunsToTheEndAndWritesAReport) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  ASSERT_TRUE(std::filesystem::exists(report()));
}

TEST_F(DemoTest, ReportPassesQpdfCheck) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto check = run_command("qpdf --check " + quote(report()) + " 2>&1");
  EXPECT_EQ(check.exit_code, 0) << check.output;
}

TEST_F(DemoTest, ReportTextIsExtractable) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto text = testing::pdf_text(report());
  for (const char* expected : {"Phantom, Maxillo", "MAXILLO-PHANTOM-001", "Synthetic craniofacial phantom", "CT",
                               "skin, frontal", "skin, lateral", "bone, oblique", "Frankfort frame", "Case contents", "SNA", "ANB",
                               "surface-skin", "page 1 of"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
}

TEST_F(DemoTest, ReportHasRealRenderedViews) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  EXPECT_GE(testing::pdf_page_count(report()), 1);
  auto views = testing::pdf_images(report(), folder_->path() / "images");
  EXPECT_EQ(views.size(), 6u) << "frontal, lateral and oblique views of skin and of bone expected";
  for (const auto& view : views) {
    EXPECT_GT(view.distinct_colours, 50u) << view.file << " looks flat";
    EXPECT_GT(view.foreground_fraction, 0.05) << view.file << " looks blank";
    EXPECT_LT(view.foreground_fraction, 0.95) << view.file << " has no background";
  }
}

TEST_F(DemoTest, ReportIsStoredInTheArchiveAndVerifies) {
  auto archive = folder_->path() / "out" / "archive";
  auto verify = run_command(std::string(MAXILLO_BINARY) + " --archive " + quote(archive) + " verify 2>&1");
  EXPECT_EQ(verify.exit_code, 0) << verify.output;
  auto show = run_command(std::string(MAXILLO_BINARY) + " --json --archive " + quote(archive) + " show case:1 2>/dev/null");
  for (const char* kind : {"\"report\"", "\"surface-skin\"", "\"render-bone-lateral\"", "\"landmarks\""})
    EXPECT_NE(show.output.find(kind), std::string::npos) << kind << " missing in " << show.output;
}

// For a PACS: the report as a DICOM Encapsulated PDF filed into the patient's study.
TEST_F(DemoTest, ReportAsEncapsulatedPdfIsFiledIntoTheStudy) {
  ASSERT_EQ(demo_.exit_code, 0);
  auto out = folder_->path() / "out";
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(out / "archive");
  auto report = run_command(maxillo + " report MAXILLO-PHANTOM-001 --out " + quote(out / "pacs.pdf") + " --dicom " +
                            quote(out / "pacs.dcm") + " --store-dicom 2>&1");
  ASSERT_EQ(report.exit_code, 0) << report.output;
  // DCMTK's own tool takes the document back out, byte for byte.
  ASSERT_EQ(run_command("dcm2pdf " + quote(out / "pacs.dcm") + " " + quote(out / "back.pdf")).exit_code, 0);
  EXPECT_EQ(run_command("cmp -s " + quote(out / "pacs.pdf") + " " + quote(out / "back.pdf")).exit_code, 0);
  auto dump = run_command("dcmdump " + quote(out / "pacs.dcm") + " 2>/dev/null");
  EXPECT_NE(dump.output.find("EncapsulatedPDFStorage"), std::string::npos);
  EXPECT_NE(dump.output.find("[Phantom^Maxillo]"), std::string::npos);

  auto shown = Json::parse(run_command(maxillo + " --json show case:1 2>/dev/null").output);
  int reports = 0;
  for (const auto& series : shown.at("item").at("series"))
    if (series.at("role") == "report" && series.at("modality") == "DOC") ++reports;
  EXPECT_EQ(reports, 1);
}

// The same phantom is the same scan (UIDs derived from it): a second demo into the same folder
// re-imports nothing and reuses the stored surfaces.
TEST_F(DemoTest, SecondRunIsIdempotent) {
  ASSERT_EQ(demo_.exit_code, 0);
  auto again = run_command(std::string(MAXILLO_BINARY) + " --json demo --out " + quote(folder_->path() / "out") +
                           " 2>/dev/null");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  auto summary = Json::parse(again.output);
  EXPECT_EQ(summary.at("imported"), 0);
  EXPECT_GT(summary.at("already_archived").get<int>(), 100);
  EXPECT_EQ(summary.at("surfaces_reused"), true);
  auto series = run_command(std::string(MAXILLO_BINARY) + " --json --archive " + quote(folder_->path() / "out" / "archive") +
                            " list series 2>/dev/null");
  int ct_series = 0;
  for (const auto& entry : Json::parse(series.output)) ct_series += entry.at("modality") == "CT";
  EXPECT_EQ(ct_series, 1) << series.output;
}

}  // namespace
}  // namespace maxillo
