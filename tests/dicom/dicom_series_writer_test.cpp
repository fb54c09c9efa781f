// The CT series writer: files readable by dcmdump and DCMTK, geometry attributes that
// reproduce the volume's LPS placement, UTF-8 names intact, and fast enough for samples.
#include "dicom/dicom_series_writer.h"
#include "dicom/dicom_uid.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include "core/error.h"
#include "dicom/dicom_fixture.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

Volume ramp_volume(Eigen::Vector3i size, Eigen::Vector3d spacing, Eigen::Vector3d origin, Eigen::Matrix3d direction) {
  Volume volume;
  volume.geometry.size = size;
  volume.geometry.spacing = spacing;
  volume.geometry.origin = origin;
  volume.geometry.direction = direction;
  volume.hu.resize(size_t(volume.geometry.voxel_count()));
  for (size_t n = 0; n < volume.hu.size(); ++n) volume.hu[n] = int16_t(int(n % 4001) - 1024);
  return volume;
}

struct LoadedSlice {
  DcmFileFormat file;
  DcmDataset& data() { return *file.getDataset(); }
  std::string text(const DcmTagKey& tag) {
    OFString value;
    data().findAndGetOFStringArray(tag, value);
    return value.c_str();
  }
  double number(const DcmTagKey& tag, unsigned long index) {
    Float64 value = NAN;
    data().findAndGetFloat64(tag, value, index);
    return value;
  }
};

void load(LoadedSlice& slice, const std::filesystem::path& path) {
  ASSERT_TRUE(slice.file.loadFile(path.c_str()).good()) << path;
}

TEST(DicomSeriesWriter, GeometryAttributesReproduceTheVolumePlacement) {
  testing::TemporaryFolder folder;
  Eigen::Matrix3d direction = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Volume volume = ramp_volume({7, 5, 4}, {0.4, 0.5, 1.25}, {-12.5, 30.25, -100}, direction);
  SeriesMetadata metadata;
  metadata.patient_name = "Müller-Łukasz^Zoë";
  metadata.patient_id = "P-001";
  metadata.study_date = "20240102";
  WrittenSeries written = write_ct_series(volume, metadata, folder.path(), "ct");
  ASSERT_EQ(written.files.size(), 4u);
  EXPECT_EQ(written.files[2].filename(), "ct0002.dcm");

  for (int k = 0; k < 4; ++k) {
    LoadedSlice slice;
    load(slice, written.files[k]);
    EXPECT_EQ(slice.text(DCM_SOPClassUID), UID_CTImageStorage);
    EXPECT_EQ(slice.file.getDataset()->getOriginalXfer(), EXS_LittleEndianExplicit);
    EXPECT_EQ(slice.text(DCM_InstanceNumber), std::to_string(k + 1));
    EXPECT_EQ(slice.text(DCM_SeriesInstanceUID), written.series_instance_uid);
    EXPECT_EQ(slice.text(DCM_SpecificCharacterSet), "ISO_IR 192");
    EXPECT_EQ(slice.text(DCM_PatientName), "Müller-Łukasz^Zoë");
    Eigen::Vector3d expected = volume.geometry.world(Eigen::Vector3d(0, 0, k));
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(slice.number(DCM_ImagePositionPatient, axis), expected[axis], 1e-6);
      EXPECT_NEAR(slice.number(DCM_ImageOrientationPatient, axis), direction(axis, 0), 1e-8);
      EXPECT_NEAR(slice.number(DCM_ImageOrientationPatient, 3 + axis), direction(axis, 1), 1e-8);
    }
    EXPECT_DOUBLE_EQ(slice.number(DCM_PixelSpacing, 0), 0.5);  // between rows (j)
    EXPECT_DOUBLE_EQ(slice.number(DCM_PixelSpacing, 1), 0.4);  // between columns (i)
    EXPECT_DOUBLE_EQ(slice.number(DCM_SliceThickness, 0), 1.25);
    EXPECT_DOUBLE_EQ(slice.number(DCM_SpacingBetweenSlices, 0), 1.25);
    Uint16 rows = 0, columns = 0, representation = 0;
    slice.data().findAndGetUint16(DCM_Rows, rows);
    slice.data().findAndGetUint16(DCM_Columns, columns);
    slice.data().findAndGetUint16(DCM_PixelRepresentation, representation);
    EXPECT_EQ(rows, 5);
    EXPECT_EQ(columns, 7);
    EXPECT_EQ(representation, 1);
    const Uint16* pixels = nullptr;
    unsigned long count = 0;
    ASSERT_TRUE(slice.data().findAndGetUint16Array(DCM_PixelData, pixels, &count).good());
    ASSERT_EQ(count, 35u);
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 7; ++i) EXPECT_EQ(int16_t(pixels[i + 7 * j]), volume.at(i, j, k));
  }
}

TEST(DicomSeriesWriter, EverySliceHasItsOwnSopInstanceUid) {
  testing::TemporaryFolder folder;
  Volume volume = ramp_volume({4, 4, 6}, {1, 1, 1}, {0, 0, 0}, Eigen::Matrix3d::Identity());
  WrittenSeries written = write_ct_series(volume, {}, folder.path());
  std::set<std::string> uids;
  for (const auto& path : written.files) {
    LoadedSlice slice;
    load(slice, path);
    uids.insert(slice.text(DCM_SOPInstanceUID));
    EXPECT_EQ(slice.text(DCM_StudyInstanceUID), written.study_instance_uid);
  }
  EXPECT_EQ(uids.size(), 6u);
  EXPECT_NE(written.study_instance_uid, written.series_instance_uid);
}

TEST(DicomSeriesWriter, DcmdumpReadsTheFiles) {
  testing::TemporaryFolder folder;
  Volume volume = ramp_volume({8, 8, 2}, {1, 1, 2}, {0, 0, 0}, Eigen::Matrix3d::Identity());
  SeriesMetadata metadata;
  metadata.patient_name = "Müller-Łukasz^Zoë";
  WrittenSeries written = write_ct_series(volume, metadata, folder.path());
  auto dump = folder / "dump.txt";
  std::string command = "dcmdump -q +U8 " + written.files[1].string() + " > " + dump.string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(dump);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Müller-Łukasz^Zoë"), std::string::npos) << text;
  EXPECT_NE(text.find("(0020,0032)"), std::string::npos);
  EXPECT_EQ(text.find("E: "), std::string::npos) << text;
}

// Speed is measured by `maxillo bench import`, which writes its input with this writer.
TEST(DicomSeriesWriter, NamedSeriesIsWrittenIdenticallyTwice) {
  testing::TemporaryFolder folder;
  Volume volume = ramp_volume({8, 8, 5}, {1, 1, 2}, {0, 0, 0}, Eigen::Matrix3d::Identity());
  SeriesMetadata metadata;
  metadata.study_instance_uid = derived_uid("study seed");
  metadata.series_instance_uid = derived_uid("series seed");
  auto first = write_ct_series(volume, metadata, folder / "first");
  auto second = write_ct_series(volume, metadata, folder / "second");
  ASSERT_EQ(first.files.size(), 5u);
  for (size_t k = 0; k < first.files.size(); ++k) {
    EXPECT_EQ(testing::read_text(first.files[k]), testing::read_text(second.files[k])) << k;
    LoadedSlice slice;
    load(slice, first.files[k]);
    EXPECT_EQ(slice.text(DCM_SOPInstanceUID), metadata.series_instance_uid + "." + std::to_string(k + 1));
  }
}

TEST(DicomSeriesWriter, DerivedUidsAreValidAndDependOnTheSeedOnly) {
  auto uid = derived_uid("seed");
  EXPECT_EQ(uid, derived_uid("seed"));
  EXPECT_NE(uid, derived_uid("seed2"));
  EXPECT_EQ(uid.rfind("2.25.", 0), 0u);
  EXPECT_LE(uid.size(), 44u);  // leaves room for .<instance number> within the 64-character limit
  EXPECT_EQ(uid.find_first_not_of("0123456789.", 0), std::string::npos);
}

TEST(DicomSeriesWriter, UnwritableFolderIsAnErrorNamingIt) {
  testing::TemporaryFolder folder;
  std::ofstream(folder / "file") << "x";
  Volume volume = ramp_volume({2, 2, 1}, {1, 1, 1}, {0, 0, 0}, Eigen::Matrix3d::Identity());
  try {
    write_ct_series(volume, {}, folder / "file" / "sub");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kWriteFailed);
    EXPECT_NE(std::string(e.what()).find("file"), std::string::npos);
  }
}

}  // namespace
}  // namespace maxillo
