// Issue 29, faults 3 and 7, in the codec: compressed slices are read (every transfer syntax
// `serve` accepts, made by DCMTK's own tools) and malformed fragments refused before DCMTK's
// decoders see them; what a UID is. What the import refuses, and that it archives nothing of it:
// tests/archive/image_input_checks_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "core/atomic_file.h"
#include "dicom/dicom_fixture.h"
#include "dicom/dicom_header.h"
#include "dicom/dicom_slice_reader.h"
#include "dicom/dicom_uid.h"
#include "support/run_command.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

struct Codec {
  const char* tool;
  const char* options;
  const char* transfer_syntax;
};

// DCMTK 3.6.7's compressors, each lossless, so the pixels read back must equal the native ones.
const Codec kCodecs[] = {
    {"dcmcjpeg", "+e1", "1.2.840.10008.1.2.4.70"},  // JPEG lossless, first-order prediction
    {"dcmcjpeg", "+el", "1.2.840.10008.1.2.4.57"},  // JPEG lossless, any selection value
    {"dcmcrle", "", "1.2.840.10008.1.2.5"},         // RLE lossless
    {"dcmcjpls", "+el", "1.2.840.10008.1.2.4.80"},  // JPEG-LS lossless
};

TEST(CompressedSlices, EveryLosslessSyntaxReadsBackTheNativePixels) {
  TemporaryFolder folder;
  auto series = testing::write_series(folder / "native", 2, "P1");
  for (const auto& codec : kCodecs) {
    if (!testing::tool_available(codec.tool)) GTEST_SKIP() << codec.tool << " is not installed (the dcmtk package)";
    SCOPED_TRACE(std::string(codec.tool) + " " + codec.options);
    for (const auto& native : series.files) {
      const auto compressed = folder / (std::string(codec.tool) + codec.options + native.filename().string());
      auto run = testing::run_command(std::string(codec.tool) + " " + codec.options + " " + testing::quote(native) +
                                      " " + testing::quote(compressed) + " 2>&1");
      ASSERT_EQ(run.exit_code, 0) << run.output;
      auto header = parse_instance_header(read_file(compressed), compressed);
      EXPECT_EQ(header.transfer_syntax_uid, codec.transfer_syntax);
      EXPECT_EQ(decode_dicom_slice(read_file(compressed), compressed).hu, read_dicom_slice(native).hu);
    }
  }
}

// `native` compressed by `tool` into `target`: the file's bytes.
std::vector<std::byte> compressed_with(const std::string& tool, const std::filesystem::path& native,
                                       const std::filesystem::path& target) {
  auto run = testing::run_command(tool + " " + testing::quote(native) + " " + testing::quote(target) + " 2>&1");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return read_file(target);
}

// Where the first fragment's bytes begin in an encapsulated file: past the Basic Offset Table's
// item and the fragment's item tag and length.
std::vector<std::byte>::iterator first_fragment(std::vector<std::byte>& bytes) {
  const std::vector<std::byte> item{std::byte(0xfe), std::byte(0xff), std::byte(0x00), std::byte(0xe0)};
  auto at = std::search(bytes.begin(), bytes.end(), item.begin(), item.end());
  if (at == bytes.end()) return at;
  uint32_t table_length = 0;
  std::memcpy(&table_length, &*(at + 4), 4);
  return at + 8 + table_length + 8;
}

// The file of a one-slice series of `folder`, compressed by `command` (a DCMTK tool and its
// options) into `folder / name`.
std::vector<std::byte> one_slice_compressed_by(const std::string& command, const TemporaryFolder& folder,
                                               const std::string& name) {
  const auto native = testing::write_series(folder / "native", 1, "P1").files.front();
  return compressed_with(command, native, folder / name);
}

// `bytes` decoded as a slice must fail with a message containing `expected`.
void expect_refused(const std::vector<std::byte>& bytes, const std::filesystem::path& file,
                    const std::string& expected) {
  try {
    decode_dicom_slice(bytes, file);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

// An RLE fragment whose header sends a segment beyond the fragment (a fuzzing finding: DCMTK's
// decoder read past it, SEGV) is refused naming the segment; dcmcrle's own files read (above).
TEST(CompressedSlices, AnRleSegmentOffsetBeyondItsFragmentIsRefused) {
  if (!testing::tool_available("dcmcrle")) GTEST_SKIP() << "dcmcrle is not installed (the dcmtk package)";
  TemporaryFolder folder;
  auto bytes = one_slice_compressed_by("dcmcrle", folder, "rle.dcm");
  const auto header = first_fragment(bytes);
  ASSERT_NE(header, bytes.end());
  uint32_t segments = 0;
  std::memcpy(&segments, &*header, 4);
  ASSERT_EQ(segments, 2u);  // 16-bit pixels: a segment per byte
  const uint32_t far_away = 50333056;
  std::memcpy(&*(header + 8), &far_away, 4);
  expect_refused(bytes, folder / "rle.dcm", "fragment 1 has RLE segment 2 at byte 50333056");
}

// A JPEG stream with a TEM marker before its start of frame (a fuzzing finding: DCMTK's scan for
// the bit depth spun on it for ever) is refused naming the marker's place; dcmcjpeg's own files
// read (above).
TEST(CompressedSlices, AJpegTemMarkerBeforeTheStartOfFrameIsRefused) {
  if (!testing::tool_available("dcmcjpeg")) GTEST_SKIP() << "dcmcjpeg is not installed (the dcmtk package)";
  TemporaryFolder folder;
  auto bytes = one_slice_compressed_by("dcmcjpeg +e1", folder, "jpeg.dcm");
  const auto stream = first_fragment(bytes);
  ASSERT_NE(stream, bytes.end());
  ASSERT_EQ(stream[0], std::byte(0xff));  // the stream opens with its start of image, FFD8
  ASSERT_EQ(stream[1], std::byte(0xd8));
  stream[2] = std::byte(0xff);  // the marker after it becomes a TEM
  stream[3] = std::byte(0x01);
  expect_refused(bytes, folder / "jpeg.dcm", "fragment 1 has a TEM marker (FF01) at byte 2 before its start of frame");
}

TEST(UidFault, FollowsPs35WithLeadingZerosToleratedOnlyWhenAsked) {
  EXPECT_FALSE(uid_fault("1.2.840.10008.1.2.4.70"));
  EXPECT_FALSE(uid_fault("0.1"));
  EXPECT_TRUE(uid_fault(""));
  EXPECT_TRUE(uid_fault("1.2."));
  EXPECT_TRUE(uid_fault(".1.2"));
  EXPECT_TRUE(uid_fault("1.2a"));
  EXPECT_TRUE(uid_fault(std::string(65, '1')));
  EXPECT_FALSE(uid_fault(std::string(64, '1')));
  EXPECT_TRUE(uid_fault("1.02.3"));
  EXPECT_FALSE(uid_fault("1.02.3", LeadingZeros::Tolerated));
  EXPECT_NE(uid_fault(std::string("1.2\0", 4))->find("byte 0"), std::string::npos);
}

}  // namespace
}  // namespace maxillo
