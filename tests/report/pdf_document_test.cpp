#include "report/pdf_document.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "core/error.h"
#include "support/pdf_tools.h"
#include "report/fonts.h"

namespace maxillo::report {
namespace {
namespace fs = std::filesystem;
using namespace maxillo::testing;

class PdfDocumentTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("maxillo-pdf-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
    style_.regular_font = resolve_font("DejaVuSans.ttf");
    style_.bold_font = resolve_font("DejaVuSans-Bold.ttf");
    style_.header_left = "Test header";
    style_.header_right = "Ærø, Åsa";
    style_.footer_text = "Test footer";
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
  PageStyle style_;
};

TEST_F(PdfDocumentTest, EveryPageHasHeaderFooterAndPageNofM) {
  PdfDocument pdf(style_);
  pdf.heading("First", HeadingLevel::Title);
  for (int i = 0; i < 3; ++i) pdf.new_page();
  ASSERT_EQ(pdf.page_count(), 4);
  pdf.save(folder_ / "pages.pdf");
  EXPECT_EQ(pdf_page_count(folder_ / "pages.pdf"), 4);
  const auto text = pdf_text(folder_ / "pages.pdf");
  EXPECT_EQ(count_of(text, "Test footer"), 4u);
  EXPECT_EQ(count_of(text, "Ærø, Åsa"), 4u);
  for (int n = 1; n <= 4; ++n) EXPECT_NE(text.find("page " + std::to_string(n) + " of 4"), std::string::npos);
  EXPECT_EQ(run_command("qpdf --check " + quote(folder_ / "pages.pdf")).exit_code, 0);
}

// The fonts' ToUnicode maps are real ToUnicode CMaps (libharu's were encoding CMaps, which
// poppler reported on every page): extraction gives the characters back with no warning.
TEST_F(PdfDocumentTest, TextExtractsThroughAValidToUnicodeMap) {
  PdfDocument pdf(style_);
  pdf.heading("Ærø, Åsa · 1.00 × 0.50 mm ± 2° — Zürich", HeadingLevel::Title);
  pdf.paragraph("Distraction ≤ 10 mm, SNA 82.0°");
  pdf.save(folder_ / "unicode.pdf");
  const auto extraction = run_command("pdftotext -enc UTF-8 " + quote(folder_ / "unicode.pdf") + " - 2>&1");
  EXPECT_EQ(extraction.exit_code, 0);
  EXPECT_EQ(extraction.output.find("ToUnicode"), std::string::npos) << extraction.output;
  EXPECT_EQ(extraction.output.find("Syntax Warning"), std::string::npos) << extraction.output;
  EXPECT_NE(extraction.output.find("Ærø, Åsa · 1.00 × 0.50 mm ± 2° — Zürich"), std::string::npos) << extraction.output;
  EXPECT_NE(extraction.output.find("Distraction ≤ 10 mm, SNA 82.0°"), std::string::npos) << extraction.output;
  const auto qdf = folder_ / "unicode-qdf.pdf";
  ASSERT_EQ(
      run_command("qpdf --qdf --object-streams=disable " + quote(folder_ / "unicode.pdf") + " " + quote(qdf)).exit_code,
      0);
  EXPECT_EQ(run_command("grep -a -c beginbfrange " + quote(qdf)).output, "6\n") << "3 blocks in each of 2 fonts";
}

TEST_F(PdfDocumentTest, LongTableBreaksAcrossPagesRepeatingItsHeader) {
  PdfDocument pdf(style_);
  Table table{{{"Measurement", 3, Align::Left}, {"Value", 1, Align::Right}, {"Norm", 1, Align::Right}}, {}};
  for (int r = 1; r <= 150; ++r)
    table.rows.push_back({"item " + std::to_string(r), std::to_string(r * 0.5), "±" + std::to_string(r)});
  pdf.table(table);
  const int pages = pdf.page_count();
  EXPECT_GE(pages, 3);  // ~20 pt per row, ~690 pt per page
  pdf.save(folder_ / "table.pdf");
  EXPECT_EQ(pdf_page_count(folder_ / "table.pdf"), pages);
  const auto text = pdf_text(folder_ / "table.pdf");
  EXPECT_EQ(count_of(text, "Measurement"), static_cast<std::size_t>(pages));  // header on every page
  for (int r : {1, 75, 150}) EXPECT_NE(text.find("item " + std::to_string(r) + "\n"), std::string::npos) << r;
}

TEST_F(PdfDocumentTest, LongParagraphWrapsWithinTheMargins) {
  PdfDocument pdf(style_);
  std::string text;
  for (int i = 0; i < 400; ++i) text += "Łukasz" + std::to_string(i) + " ";
  text += std::string(200, 'W');  // one word wider than the line: split between characters
  pdf.paragraph(text);
  pdf.save(folder_ / "wrap.pdf");
  // Text that ran past the right margin would be cut by pdftotext's -x/-W crop box.
  const double text_right_pt = 595.276 - 20 * 72 / 25.4;
  const auto cropped = run_command("pdftotext -enc UTF-8 -x 0 -y 0 -W " + std::to_string(int(text_right_pt) + 1) +
                                   " -H 842 " + quote(folder_ / "wrap.pdf") + " - 2>/dev/null")
                           .output;
  for (int i : {0, 199, 399}) EXPECT_NE(cropped.find("Łukasz" + std::to_string(i)), std::string::npos) << i;
  EXPECT_GE(pdf.page_count(), 2);
}

TEST_F(PdfDocumentTest, MissingOrInvalidImagesAreErrorsNamingTheFile) {
  PdfDocument pdf(style_);
  try {
    pdf.figure({folder_ / "absent.png", "x"}, 50);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kFileNotFound);
    EXPECT_NE(std::string(e.what()).find("absent.png"), std::string::npos);
  }
  std::ofstream(folder_ / "fake.png") << "not a png at all";
  try {
    pdf.figure({folder_ / "fake.png", "x"}, 50);  // libharu's own error, turned into maxillo::Error
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("fake.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("libharu"), std::string::npos) << e.what();
  }
  // The document is still usable after a reported error.
  pdf.paragraph("still fine");
  pdf.save(folder_ / "after-error.pdf");
  EXPECT_NE(pdf_text(folder_ / "after-error.pdf").find("still fine"), std::string::npos);
}

TEST_F(PdfDocumentTest, SavingIntoAMissingFolderFailsWithoutLeavingAFile) {
  PdfDocument pdf(style_);
  pdf.paragraph("x");
  EXPECT_THROW(pdf.save(folder_ / "no" / "such" / "out.pdf"), Error);
  EXPECT_FALSE(fs::exists(folder_ / "no"));
}

TEST_F(PdfDocumentTest, MissingFontIsAnError) {
  style_.bold_font = folder_ / "missing-bold.ttf";
  try {
    PdfDocument pdf(style_);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kFileNotFound);
    EXPECT_NE(std::string(e.what()).find("missing-bold.ttf"), std::string::npos);
  }
}

}  // namespace
}  // namespace maxillo::report
