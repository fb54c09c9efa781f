// read_volume_file: MetaImage and NRRD files written here byte by byte, with known geometry.
#include "imaging/volume_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

constexpr int kNx = 4, kNy = 3, kNz = 2;

uint16_t stored_value(int n) { return uint16_t(1000 + 37 * n); }

// kNx*kNy*kNz big-endian uint16 values.
void write_raw_big_endian(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  for (int n = 0; n < kNx * kNy * kNz; ++n) {
    const uint16_t v = stored_value(n);
    const char bytes[2] = {char(v >> 8), char(v & 0xff)};
    out.write(bytes, 2);
  }
}

void expect_known_volume(const Volume& v, const Eigen::Matrix3d& direction) {
  EXPECT_EQ(v.geometry.size, Eigen::Vector3i(kNx, kNy, kNz));
  EXPECT_TRUE(v.geometry.spacing.isApprox(Eigen::Vector3d(0.5, 0.75, 2.5)));
  EXPECT_TRUE(v.geometry.origin.isApprox(Eigen::Vector3d(-10, 20, 30.5)));
  EXPECT_TRUE(v.geometry.direction.isApprox(direction)) << v.geometry.direction;
  ASSERT_EQ(v.hu.size(), size_t(kNx * kNy * kNz));
  for (int n = 0; n < kNx * kNy * kNz; ++n) EXPECT_EQ(v.hu[size_t(n)], stored_value(n) - 1024);
}

TEST(VolumeFile, ReadsMetaImageGeometryAndAppliesTheOffset) {
  TemporaryFolder folder("volume-file");
  write_raw_big_endian(folder / "data.raw");
  std::ofstream(folder / "v.mhd") << "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\nElementType = MET_USHORT\n"
                                     "ElementSpacing = 0.5 0.75 2.5\nOffset = -10 20 30.5\n"
                                     "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nElementByteOrderMSB = True\n"
                                     "ElementDataFile = data.raw\n";
  // MetaImage's TransformMatrix lists the axes one after the other: i = (0,1,0), j = (-1,0,0).
  Eigen::Matrix3d direction;
  direction << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  expect_known_volume(read_volume_file(folder / "v.mhd", {.hu_offset = -1024}), direction);
}

TEST(VolumeFile, ReadsNrrd) {
  TemporaryFolder folder("volume-file-nrrd");
  write_raw_big_endian(folder / "data.raw");
  std::ofstream(folder / "v.nhdr") << "NRRD0004\ntype: unsigned short\ndimension: 3\nspace: left-posterior-superior\n"
                                      "sizes: 4 3 2\nspace directions: (0.5,0,0) (0,0.75,0) (0,0,2.5)\n"
                                      "space origin: (-10,20,30.5)\nendian: big\nencoding: raw\ndata file: data.raw\n";
  expect_known_volume(read_volume_file(folder / "v.nhdr", {.hu_offset = -1024}), Eigen::Matrix3d::Identity());
}

ErrorCode code_of_reading_volume(const std::filesystem::path& path, const VolumeFileOptions& options = {}) {
  try {
    read_volume_file(path, options);
  } catch (const Error& e) {
    EXPECT_EQ(e.subject(), path.string());
    return e.code();
  }
  ADD_FAILURE() << path << " was accepted";
  return ErrorCode::kProcessing;
}

TEST(VolumeFile, RefusesWhatIsNotAScalarVolumeInHuRange) {
  TemporaryFolder folder("volume-file-bad");
  write_raw_big_endian(folder / "data.raw");
  std::ofstream(folder / "flat.mhd") << "ObjectType = Image\nNDims = 2\nDimSize = 4 6\nElementType = MET_USHORT\n"
                                        "ElementByteOrderMSB = True\nElementDataFile = data.raw\n";
  EXPECT_EQ(code_of_reading_volume(folder / "flat.mhd"), ErrorCode::kUnsupportedSyntax);
  std::ofstream(folder / "v.mhd") << "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\nElementType = MET_USHORT\n"
                                     "ElementByteOrderMSB = True\nElementDataFile = data.raw\n";
  EXPECT_EQ(code_of_reading_volume(folder / "v.mhd", {.hu_offset = 32000}), ErrorCode::kBadValue);
  std::ofstream(folder / "short.mhd") << "ObjectType = Image\nNDims = 3\nDimSize = 40 30 20\nElementType = MET_USHORT\n"
                                         "ElementDataFile = data.raw\n";
  EXPECT_EQ(code_of_reading_volume(folder / "short.mhd"), ErrorCode::kBadValue);
  std::ofstream(folder / "v.png") << "x";
  EXPECT_EQ(code_of_reading_volume(folder / "v.png"), ErrorCode::kUnsupportedSyntax);
  EXPECT_EQ(code_of_reading_volume(folder / "absent.mhd"), ErrorCode::kFileNotFound);
}

}  // namespace
}  // namespace maxillo
