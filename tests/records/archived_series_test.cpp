// An archived series read back as a volume: its errors name the files a person imported.
#include <gtest/gtest.h>

#include "archive_fixture.h"
#include "records/archived_series.h"

namespace maxillo::records {
namespace {

using testing::TemporaryFolder;

TEST(ArchivedSeries, AMissingSliceIsReportedWithTheImportedFileNamesNotObjectHashes) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 8, "P1");
  std::filesystem::remove(written.files[4]);  // a gap between slices 3 and 5
  Archive archive = Archive::open(folder / "archive", OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, testing::quiet());
  try {
    load_archived_series(archive, 1);
    FAIL() << "a series with a gap must be refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kInconsistentSeries);
    const std::string message = e.what();
    EXPECT_NE(message.find((folder / "in").string()), std::string::npos) << message;
    EXPECT_NE(message.find("archived as"), std::string::npos) << message;
    EXPECT_NE(e.reason().find("slice0003.dcm"), std::string::npos) << e.reason();
  }
}

}  // namespace
}  // namespace maxillo::records
