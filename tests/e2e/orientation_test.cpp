// Issue 28, section 3, end to end: the real cadaver head as a careless conversion gives it (the
// raw slices as a MetaImage with an identity direction: no HU offset, the vertex at -z) is
// flagged at conversion, refused by planning, marked in `list cases` and on every report page,
// and goes on once a person confirms it. Skipped where the data are absent.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "support/cadaver_dicom.h"
#include "support/cthead_metaimage.h"
#include "support/pdf_tools.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

TEST(OrientationCheck, AHeaderThatContradictsTheAnatomyIsFlaggedRefusedAndConfirmedByHand) {
  if (!std::filesystem::exists(testing::cthead_slices() / "CThead.113"))
    GTEST_SKIP() << "real data absent: " << testing::cthead_slices();
  testing::TemporaryFolder folder("maxillo-orientation");
  testing::write_cthead_metaimage(folder.path(), "raw.mhd");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder / "archive");

  const auto converted =
      run_command(maxillo + " convert " + quote(folder / "raw.mhd") + " --out " + quote(folder / "dicom") + " 2>&1");
  ASSERT_EQ(converted.exit_code, 0) << converted.output;
  EXPECT_NE(converted.output.find("the vertex points inferior"), std::string::npos) << converted.output;
  EXPECT_NE(converted.output.find("mapped to -1000 and 40 HU"), std::string::npos) << converted.output;
  const auto imported = run_command(maxillo + " import " + quote(folder / "dicom") + " 2>&1");
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  EXPECT_NE(imported.output.find("case:1: the header contradicts the anatomy"), std::string::npos)
      << "said at import: " << imported.output;

  const auto checked = run_command(maxillo + " orientation 1 2>&1");
  EXPECT_EQ(checked.exit_code, 26) << checked.output;
  EXPECT_NE(checked.output.find("the header contradicts the anatomy"), std::string::npos) << checked.output;
  ASSERT_EQ(run_command(maxillo + " -q plan create 1 --advance 6").exit_code, 0);
  const auto refused = run_command(maxillo + " plan apply 1 --out " + quote(folder / "plan") + " 2>&1");
  EXPECT_EQ(refused.exit_code, 26) << refused.output;
  EXPECT_NE(refused.output.find("planning refused"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("orientation case:1 --confirm"), std::string::npos) << refused.output;
  EXPECT_NE(run_command(maxillo + " list cases").output.find("CONTRADICTS"), std::string::npos);
  EXPECT_NE(run_command(maxillo + " show case:1").output.find("contradicts_header: true"), std::string::npos);

  ASSERT_EQ(run_command(maxillo + " -q report 1 --out " + quote(folder / "flagged.pdf")).exit_code, 0);
  const std::string text = testing::pdf_text(folder / "flagged.pdf");
  const int pages = testing::pdf_page_count(folder / "flagged.pdf");
  EXPECT_GE(pages, 2);
  EXPECT_EQ(testing::count_of(text, "CONTRADICTS THE ANATOMY"), size_t(pages)) << "the banner on every page";

  const auto confirmed = run_command(maxillo + " orientation 1 --confirm 2>&1");
  EXPECT_EQ(confirmed.exit_code, 0) << confirmed.output;
  const auto planned = run_command(maxillo + " plan apply 1 --out " + quote(folder / "plan") + " 2>&1");
  EXPECT_EQ(planned.output.find("planning refused"), std::string::npos) << planned.output;
  // The next step is the landmarks: none attached, so they are looked for on this (reversed)
  // head, which has no sella or nasion where a head has them: an input error, not a plan.
  EXPECT_EQ(planned.exit_code, 26) << planned.output;
  EXPECT_NE(planned.output.find("case:1"), std::string::npos) << planned.output;
  EXPECT_NE(run_command(maxillo + " list cases").output.find("confirmed"), std::string::npos);
  ASSERT_EQ(run_command(maxillo + " -q report 1 --out " + quote(folder / "confirmed.pdf")).exit_code, 0);
  const std::string confirmed_text = testing::pdf_text(folder / "confirmed.pdf");
  EXPECT_EQ(confirmed_text.find("CONTRADICTS THE ANATOMY"), std::string::npos);
  EXPECT_NE(confirmed_text.find("Confirmed by hand"), std::string::npos);
}

// The example: the cadaver head converted with its y axis flipped (the face at +y, a
// mirror). `--reorient` stores a corrected copy, and the copy is the correctly converted head:
// the landmarks found on it are those found on the right conversion, to the last digit.
TEST(OrientationCheck, AFlippedYAxisIsReorientedIntoTheRightHead) {
  if (!std::filesystem::exists(testing::cthead_slices() / "CThead.113"))
    GTEST_SKIP() << "real data absent: " << testing::cthead_slices();
  testing::TemporaryFolder folder("maxillo-reorient");
  testing::write_cthead_metaimage(folder.path(), "raw.mhd");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder / "archive");
  const auto converted =
      run_command(maxillo + " convert " + quote(folder / "raw.mhd") + " --out " + quote(folder / "flipped") +
                  " --direction 1,0,0,0,-1,0,0,0,-1 --origin -127.5,127.5,224 --hu-offset -1024 2>&1");
  ASSERT_EQ(converted.exit_code, 0) << converted.output;
  EXPECT_NE(converted.output.find("the face points posterior"), std::string::npos) << converted.output;
  ASSERT_EQ(run_command(maxillo + " -q import " + quote(folder / "flipped")).exit_code, 0);
  EXPECT_EQ(run_command(maxillo + " orientation 1 2>&1").exit_code, 26);

  const auto reoriented = run_command(maxillo + " orientation 1 --reorient 2>&1");
  ASSERT_EQ(reoriented.exit_code, 0) << reoriented.output;
  EXPECT_NE(reoriented.output.find("reoriented: the y axis flipped back"), std::string::npos) << reoriented.output;
  EXPECT_NE(reoriented.output.find("the header agrees with the anatomy"), std::string::npos) << reoriented.output;
  EXPECT_NE(run_command(maxillo + " list cases").output.find("agrees"), std::string::npos);
  const auto show = run_command(maxillo + " show case:1 2>&1").output;
  EXPECT_NE(show.find("unassigned"), std::string::npos) << "the original series is kept: " << show;

  const auto right = testing::wrap_cadaver_as_dicom(folder / "right");
  ASSERT_EQ(right.exit_code, 0) << right.output;
  ASSERT_EQ(run_command(maxillo + " -q landmarks detect 1 --out " + quote(folder / "reoriented.csv")).exit_code, 0);
  ASSERT_EQ(
      run_command(maxillo + " -q landmarks detect " + quote(folder / "right") + " --out " + quote(folder / "right.csv"))
          .exit_code,
      0);
  const auto read = [](const std::filesystem::path& file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(read(folder / "reoriented.csv"), read(folder / "right.csv"));
  EXPECT_EQ(run_command(maxillo + " orientation 1 --reorient 2>&1").exit_code, 26) << "nothing left to undo";
}

}  // namespace
}  // namespace maxillo
