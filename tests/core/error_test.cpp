#include "core/error.h"

#include <gtest/gtest.h>

#include <set>

namespace maxillo {

TEST(ErrorCatalogue, ExitCodesAreInTheirReservedRanges) {
  EXPECT_EQ(exit_code_for(ErrorCode::kBatchPartlyFailed), 1);
  EXPECT_EQ(exit_code_for(ErrorCode::kUsage), 2);
  for (auto code : {ErrorCode::kFileNotFound, ErrorCode::kNotDicom, ErrorCode::kTruncated,
                    ErrorCode::kUnsupportedSyntax, ErrorCode::kInconsistentSeries}) {
    EXPECT_GE(exit_code_for(code), 20);
    EXPECT_LE(exit_code_for(code), 39);
  }
  for (auto code : {ErrorCode::kWriteFailed, ErrorCode::kArchiveCorrupt, ErrorCode::kConflict}) {
    EXPECT_GE(exit_code_for(code), 40);
    EXPECT_LE(exit_code_for(code), 59);
  }
  EXPECT_GE(exit_code_for(ErrorCode::kProcessing), 60);
}

TEST(ErrorCatalogue, NamesAreUniqueAndWithoutPrefix) {
  std::set<std::string_view> names;
  for (auto code : {ErrorCode::kUsage, ErrorCode::kNotDicom, ErrorCode::kConflict, ErrorCode::kProcessing}) {
    EXPECT_TRUE(names.insert(name_of(code)).second);
    EXPECT_NE(name_of(code).front(), 'k');
  }
  EXPECT_EQ(name_of(ErrorCode::kNotDicom), "NotDicom");
}

TEST(Error, MessageNamesSubjectAndReason) {
  Error error(ErrorCode::kNotDicom, "/data/x.dcm", "no DICM prefix");
  EXPECT_STREQ(error.what(), "/data/x.dcm: no DICM prefix");
  EXPECT_EQ(error.code(), ErrorCode::kNotDicom);
}

}  // namespace maxillo
