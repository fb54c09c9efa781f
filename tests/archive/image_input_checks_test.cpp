// Issue 29, faults 4 and 7, at import: an image without its pixels is refused, and so is a UID
// that is not a UID, each naming the file and the reason; nothing of them is archived. What the
// codec reads and refuses itself (compressed slices, malformed fragments, what a UID is):
// tests/dicom/compressed_slices_test.cpp.
#include <gtest/gtest.h>

#include <functional>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include "archive/archive.h"
#include "archive_fixture.h"

namespace maxillo {
namespace {

using testing::quiet;
using testing::TemporaryFolder;

// A copy of `source` changed by `edit`, saved in the source's transfer syntax.
std::filesystem::path edited_copy(const std::filesystem::path& source, const std::filesystem::path& target,
                                  const std::function<void(DcmDataset&)>& edit) {
  DcmFileFormat file;
  EXPECT_TRUE(file.loadFile(source.c_str()).good());
  edit(*file.getDataset());
  EXPECT_TRUE(file.saveFile(target.c_str(), file.getDataset()->getOriginalXfer()).good());
  return target;
}

// Imports `file` alone into a new archive: the problem reported, and nothing archived.
ImportProblem refused_at_import(const TemporaryFolder& folder, const std::filesystem::path& file) {
  Archive archive =
      Archive::open(testing::archive_at(folder / ("archive-" + file.filename().string())), OpenMode::CreateIfMissing);
  auto report = archive.import_paths({file}, quiet());
  EXPECT_EQ(report.imported, 0u);
  EXPECT_TRUE(archive.series().empty());
  if (report.problems.size() != 1) {
    ADD_FAILURE() << file << " was not refused";
    return {};
  }
  EXPECT_EQ(report.problems[0].path, file);
  return report.problems[0];
}

TEST(ImageInputChecks, AnImageWithoutItsPixelsIsRefused) {
  TemporaryFolder folder;
  auto series = testing::write_series(folder / "in", 1, "P1");
  auto cut =
      edited_copy(series.files[0], folder / "cut.dcm", [](DcmDataset& d) { d.findAndDeleteElement(DCM_PixelData); });
  auto problem = refused_at_import(folder, cut);
  EXPECT_EQ(problem.code, ErrorCode::kTruncated);
  EXPECT_NE(problem.reason.find("without Pixel Data"), std::string::npos) << problem.reason;

  auto half = edited_copy(series.files[0], folder / "half.dcm", [](DcmDataset& d) {
    const Uint16* words = nullptr;
    unsigned long count = 0;
    ASSERT_TRUE(d.findAndGetUint16Array(DCM_PixelData, words, &count).good());
    std::vector<Uint16> first_half(words, words + count / 2);
    d.putAndInsertUint16Array(DCM_PixelData, first_half.data(), first_half.size());
  });
  problem = refused_at_import(folder, half);
  EXPECT_EQ(problem.code, ErrorCode::kTruncated);
  EXPECT_NE(problem.reason.find("holds 256 bytes"), std::string::npos) << problem.reason;
}

TEST(ImageInputChecks, UidsThatAreNotUidsAreRefusedNamingTheElement) {
  TemporaryFolder folder;
  auto series = testing::write_series(folder / "in", 1, "P1");
  struct BadUid {
    DcmTagKey tag;
    std::string uid, element;
  };
  const BadUid bad[] = {
      {DCM_SOPInstanceUID, "1.2.3/4.5", "SOP Instance UID (0008,0018)"},
      {DCM_SOPInstanceUID, "1." + std::string(299, '1'), "SOP Instance UID (0008,0018)"},
      {DCM_StudyInstanceUID, "1.2..3", "Study Instance UID (0020,000D)"},
      {DCM_SeriesInstanceUID, std::string("1.2.3\0\0.4", 9), "Series Instance UID (0020,000E)"},
  };
  int n = 0;
  for (const BadUid& b : bad) {
    auto file = edited_copy(series.files[0], folder / ("bad" + std::to_string(n++) + ".dcm"), [&](DcmDataset& d) {
      d.putAndInsertOFStringArray(b.tag, OFString(b.uid.data(), b.uid.size()));
    });
    auto problem = refused_at_import(folder, file);
    EXPECT_EQ(problem.code, ErrorCode::kBadValue);
    EXPECT_NE(problem.reason.find("is not a UID"), std::string::npos) << problem.reason;
    EXPECT_NE(problem.reason.find(b.element + " is not a UID"), std::string::npos) << problem.reason;
  }
}

TEST(ImageInputChecks, TheIndependentRunsBadFilesAreRefusedWhenPresent) {
  const auto folder = std::filesystem::path(MAXILLO_SHARED_DATA) / "bad-inputs" / "2026-11-27";
  if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "../shared/data/bad-inputs is absent";
  TemporaryFolder work;
  for (const char* name : {"sop-uid-slashes.dcm", "sop-uid-301-chars.dcm", "uid-with-nul-byte.dcm"}) {
    SCOPED_TRACE(name);
    auto problem = refused_at_import(work, folder / name);
    EXPECT_NE(problem.reason.find("is not a UID"), std::string::npos) << problem.reason;
  }
}

}  // namespace
}  // namespace maxillo
