// Black-box runs of `maxillo convert` and `maxillo surfaces` on a small synthetic head:
// a MetaImage ball of soft tissue (radius 40 mm) with a bone shell, stored as HU + 1024.
#include <Eigen/Core>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "core/json.h"
#include "support/run_command.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

const std::filesystem::path kMaxillo = MAXILLO_BINARY;
constexpr int kSize = 50;          // voxels per axis, 2 mm each
constexpr double kRadius = 40;     // mm, skin
constexpr double kBoneOuter = 34;  // mm
constexpr double kBoneInner = 28;  // mm

double hu_at(const Eigen::Vector3d& p) {
  const double d = (p - Eigen::Vector3d(49, 49, 49)).norm();
  if (d > kRadius) return -1000;
  if (d < kBoneOuter && d > kBoneInner) return 1000;
  return 30;
}

std::filesystem::path write_synthetic_head(const TemporaryFolder& folder) {
  std::ofstream raw(folder / "head.raw", std::ios::binary);
  for (int k = 0; k < kSize; ++k)
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i) {
        const uint16_t stored = uint16_t(std::lround(hu_at(2.0 * Eigen::Vector3d(i, j, k)) + 1024));
        raw.write(reinterpret_cast<const char*>(&stored), 2);  // little endian (x86)
      }
  std::ofstream(folder / "head.mhd")
      << "ObjectType = Image\nNDims = 3\nDimSize = 50 50 50\nElementType = MET_USHORT\n"
         "ElementSpacing = 2 2 2\nElementByteOrderMSB = False\nElementDataFile = head.raw\n";
  return folder / "head.mhd";
}

class Commands : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kMaxillo)) GTEST_SKIP() << kMaxillo << " is not built";
  }
  testing::CommandResult maxillo(const std::string& arguments) {
    return testing::run_command(testing::quote(kMaxillo) + " " + arguments);
  }
};

TEST_F(Commands, ConvertThenSurfaces) {
  TemporaryFolder folder("commands");
  const auto mhd = write_synthetic_head(folder);
  auto convert = maxillo("--json convert " + testing::quote(mhd) + " --out " + testing::quote(folder / "dicom") +
                         " --hu-offset -1024 --origin 10,20,30 --direction 0,1,0,-1,0,0,0,0,1 2>&1");
  ASSERT_EQ(convert.exit_code, 0) << convert.output;
  Json converted = Json::parse(convert.output);
  EXPECT_EQ(converted["files"], kSize);
  EXPECT_EQ(converted["origin_lps_mm"], Json::array({10.0, 20.0, 30.0}));

  auto surfaces =
      maxillo("--json surfaces " + testing::quote(folder / "dicom") + " --out " + testing::quote(folder / "surfaces") +
              // iso-values halfway between the phantom's steps put the surfaces on
              // the voxel boundaries, where the analytic sizes apply
              " --skin-hu -485 --bone-hu 515 --triangles 5000 --format ply");
  ASSERT_EQ(surfaces.exit_code, 0) << surfaces.output;
  Json result = Json::parse(surfaces.output);
  ASSERT_EQ(result["surfaces"].size(), 2u);
  const Json& skin = result["surfaces"][0];
  const Json& bone = result["surfaces"][1];
  EXPECT_EQ(skin["name"], "skin");
  EXPECT_EQ(skin["components"], 1);
  EXPECT_TRUE(skin["watertight"].get<bool>());
  EXPECT_LE(skin["triangles"].get<int>(), 5500);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(skin["volume_mm3"].get<double>() / (4.0 / 3.0 * pi * std::pow(kRadius, 3)), 1.0, 0.03);
  // The bone shell has an outer and an inner surface: volume = difference of the two balls.
  const double shell = 4.0 / 3.0 * pi * (std::pow(kBoneOuter, 3) - std::pow(kBoneInner, 3));
  EXPECT_NEAR(bone["volume_mm3"].get<double>() / shell, 1.0, 0.05);
  EXPECT_TRUE(std::filesystem::exists(folder / "surfaces" / "skin.ply"));
  EXPECT_TRUE(std::filesystem::exists(folder / "surfaces" / "bone.ply"));
}

// Issue 28: a cone-beam scan's grey values are not HU; `surfaces` reads them through the scan's
// own air and soft-tissue modes (its cupping undone) and says where its thresholds fell.
TEST_F(Commands, SurfacesOfAConeBeamScanSayHowItsGreyValuesWereRead) {
  TemporaryFolder folder("commands-cbct");
  ASSERT_EQ(maxillo("-q sample --cbct --spacing 2 --out " + testing::quote(folder / "cb")).exit_code, 0);
  auto surfaces = maxillo("--json surfaces " + testing::quote(folder / "cb" / "ct") + " --out " +
                          testing::quote(folder / "surfaces") + " --bone-edge half-maximum --triangles 20000");
  ASSERT_EQ(surfaces.exit_code, 0) << surfaces.output;
  const Json result = Json::parse(surfaces.output);
  const Json& grey = result["grey_values"];
  EXPECT_FALSE(grey["hounsfield_as_stored"].get<bool>());
  EXPECT_GT(grey["cupping_undone"].get<double>(), 0.02);
  EXPECT_NE(grey["reading"].get<std::string>().find("mapped to -1000 and 40 HU"), std::string::npos) << grey;
  // The sample's scanner: grey = air's grey + (HU + 1000) (ConeBeamFlavour's defaults), so 300 HU falls near 1300.
  EXPECT_NEAR(grey["bone_threshold_grey"].get<double>(), 1300, 80) << grey;
  const Json& bone = result["surfaces"][1];
  EXPECT_GT(bone["triangles"].get<int>(), 1000);
  EXPECT_GT(bone["volume_mm3"].get<double>(), 50000) << "the jaws and midface in the field";
  auto text = maxillo("surfaces " + testing::quote(folder / "cb" / "ct") + " --out " +
                      testing::quote(folder / "surfaces") + " --triangles 20000");
  EXPECT_NE(text.output.find("(bone) in the scan's values"), std::string::npos) << text.output;
}

TEST_F(Commands, RejectsBadOptionsAndInputs) {
  TemporaryFolder folder("commands-bad");
  const auto mhd = write_synthetic_head(folder);
  const std::string out = " --out " + testing::quote(folder / "out");
  EXPECT_EQ(maxillo("convert " + testing::quote(mhd) + out + " --direction 1,0,0,1,0,0,0,0,1 2>&1").exit_code, 2)
      << "axes not orthogonal";
  EXPECT_EQ(maxillo("convert " + testing::quote(mhd) + out + " --direction 1,0,0 2>&1").exit_code, 2);
  EXPECT_EQ(maxillo("surfaces " + testing::quote(folder.path()) + out + " --format off 2>&1").exit_code, 2);
  EXPECT_EQ(maxillo("surfaces " + testing::quote(folder.path()) + out + " --skin-hu -2000 2>&1").exit_code, 2);
  auto not_dicom = maxillo("surfaces " + testing::quote(folder.path()) + out + " 2>&1");
  EXPECT_EQ(not_dicom.exit_code, 22) << not_dicom.output;  // kNotDicom names the file
  EXPECT_NE(not_dicom.output.find("head."), std::string::npos) << not_dicom.output;
}

}  // namespace
}  // namespace maxillo
