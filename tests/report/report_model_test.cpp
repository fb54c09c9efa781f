#include "report/report_model.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "report/fonts.h"

namespace maxillo::report {
namespace {

TEST(FormatPersonName, FamilyCommaGivenWithUtf8Intact) {
  EXPECT_EQ(format_person_name("Müller-Łukasz^Zoë"), "Müller-Łukasz, Zoë");
  EXPECT_EQ(format_person_name("Doe^John^Quincy^Dr^Jr"), "Doe, Dr John Quincy, Jr");
  EXPECT_EQ(format_person_name("Doe"), "Doe");
  EXPECT_EQ(format_person_name("^John"), "John");
  EXPECT_EQ(format_person_name("Yamada^Tarou=山田^太郎=やまだ^たろう"), "Yamada, Tarou");
  EXPECT_EQ(format_person_name(""), "");
}

TEST(FormatDicomValues, DatesAndSex) {
  EXPECT_EQ(format_dicom_date("19750312"), "1975-03-12");
  EXPECT_EQ(format_dicom_date(""), "");
  EXPECT_EQ(format_dicom_date("1975"), "1975");
  EXPECT_EQ(format_dicom_date("1975031a"), "1975031a");
  EXPECT_EQ(format_sex("F"), "female");
  EXPECT_EQ(format_sex("M"), "male");
  EXPECT_EQ(format_sex("O"), "other");
  EXPECT_EQ(format_sex(""), "");
}

TEST(Fonts, DejaVuIsFoundByNameAndAMissingFontIsNamed) {
  auto regular = resolve_font("DejaVuSans.ttf");
  EXPECT_TRUE(std::filesystem::is_regular_file(regular)) << regular;
  try {
    resolve_font("NoSuchFont-Regular.ttf");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kFileNotFound);
    EXPECT_NE(std::string(e.what()).find("NoSuchFont-Regular.ttf"), std::string::npos) << e.what();
  }
  EXPECT_THROW(resolve_font("/nonexistent/folder/DejaVuSans.ttf"), Error);
}

}  // namespace
}  // namespace maxillo::report
