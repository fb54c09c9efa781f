// read_dicom_slice on real DICOM files: series written by write_ct_series, hand-made pixel
// encodings (8/16 bit, signed, BitsStored, MONOCHROME1, rescale), files compressed by DCMTK's
// own tools (JPEG lossless, JPEG-LS, RLE), and the refusals.
#include "dicom/dicom_slice_reader.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "dicom/dicom_series_writer.h"
#include "support/bad_dicom_files.h"
#include "support/oblique_axes.h"
#include "support/run_command.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

Volume small_ct(const Eigen::Matrix3d& direction) {
  Volume v;
  v.geometry.size = {7, 5, 4};
  v.geometry.spacing = {0.7, 0.9, 1.3};
  v.geometry.origin = {-12.5, 40.25, 101};
  v.geometry.direction = direction;
  v.hu.resize(size_t(v.geometry.voxel_count()));
  for (size_t n = 0; n < v.hu.size(); ++n) v.hu[n] = int16_t(int(n) * 97 % 4000 - 1024);
  return v;
}

ErrorCode code_of_reading(const std::filesystem::path& path, std::string* reason = nullptr) {
  try {
    read_dicom_slice(path);
  } catch (const Error& e) {
    EXPECT_EQ(e.subject(), path.string());
    if (reason) *reason = e.reason();
    return e.code();
  }
  ADD_FAILURE() << path << " was accepted";
  return ErrorCode::kProcessing;
}

TEST(DicomSliceReader, ReadsBackWhatTheSeriesWriterWrote) {
  TemporaryFolder folder("slice-reader");
  const Volume v = small_ct(testing::oblique_axes());
  WrittenSeries series = write_ct_series(v, {}, folder.path());
  for (int k = 0; k < v.geometry.size.z(); ++k) {
    DicomSlice s = read_dicom_slice(series.files[size_t(k)]);
    EXPECT_EQ(s.series_instance_uid, series.series_instance_uid);
    EXPECT_EQ(s.instance_number, k + 1);
    EXPECT_EQ(s.columns, 7);
    EXPECT_EQ(s.rows, 5);
    EXPECT_NEAR(s.column_spacing, 0.7, 1e-9);
    EXPECT_NEAR(s.row_spacing, 0.9, 1e-9);
    EXPECT_TRUE(s.row_direction.isApprox(v.geometry.direction.col(0), 1e-8));
    EXPECT_TRUE(s.column_direction.isApprox(v.geometry.direction.col(1), 1e-8));
    EXPECT_TRUE(s.position.isApprox(v.geometry.world(Eigen::Vector3d(0, 0, k)), 1e-8));
    std::vector<int16_t> expected(v.hu.begin() + 35 * k, v.hu.begin() + 35 * (k + 1));
    EXPECT_EQ(s.hu, expected);
  }
}

// A single-frame image with the given encoding; `stored` holds the raw stored values.
struct Encoding {
  int bits_allocated = 16, bits_stored = 16, pixel_representation = 0;
  std::string photometric = "MONOCHROME2";
  std::string slope = "1", intercept = "0";
};

void write_encoded(const std::filesystem::path& path, const Encoding& e, const std::vector<uint16_t>& stored) {
  DcmFileFormat file;
  DcmDataset* d = file.getDataset();
  d->putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
  d->putAndInsertString(DCM_SOPInstanceUID, "1.2.826.0.1.3680043.2.1143.1");
  d->putAndInsertString(DCM_SeriesInstanceUID, "1.2.826.0.1.3680043.2.1143.2");
  d->putAndInsertString(DCM_ImagePositionPatient, "1\\2\\3");
  d->putAndInsertString(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
  d->putAndInsertString(DCM_PixelSpacing, "0.5\\0.5");
  d->putAndInsertString(DCM_PhotometricInterpretation, e.photometric.c_str());
  d->putAndInsertString(DCM_RescaleSlope, e.slope.c_str());
  d->putAndInsertString(DCM_RescaleIntercept, e.intercept.c_str());
  d->putAndInsertUint16(DCM_SamplesPerPixel, 1);
  d->putAndInsertUint16(DCM_Rows, 2);
  d->putAndInsertUint16(DCM_Columns, Uint16(stored.size() / 2));
  d->putAndInsertUint16(DCM_BitsAllocated, Uint16(e.bits_allocated));
  d->putAndInsertUint16(DCM_BitsStored, Uint16(e.bits_stored));
  d->putAndInsertUint16(DCM_HighBit, Uint16(e.bits_stored - 1));
  d->putAndInsertUint16(DCM_PixelRepresentation, Uint16(e.pixel_representation));
  if (e.bits_allocated == 8) {
    std::vector<Uint8> bytes(stored.begin(), stored.end());
    d->putAndInsertUint8Array(DCM_PixelData, bytes.data(), bytes.size());
  } else {
    d->putAndInsertUint16Array(DCM_PixelData, stored.data(), stored.size());
  }
  ASSERT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
}

TEST(DicomSliceReader, AppliesBitsStoredSignAndRescale) {
  TemporaryFolder folder("slice-encodings");
  struct Case {
    const char* name;
    Encoding encoding;
    std::vector<uint16_t> stored;
    std::vector<int16_t> hu;
  };
  const std::vector<Case> cases = {
      {"unsigned 8 bit, slope 2", {8, 8, 0, "MONOCHROME2", "2", "-100"}, {0, 1, 128, 255}, {-100, -98, 156, 410}},
      {"unsigned 16 bit, CT offset",
       {16, 16, 0, "MONOCHROME2", "1", "-1024"},
       {0, 1024, 3000, 65535},
       {-1024, 0, 1976, 32767}},
      // 12 stored bits, signed; the unused high bits carry garbage that must be masked off.
      {"signed 12 of 16 bits",
       {16, 12, 1, "MONOCHROME2", "1", "0"},
       {0x0800, 0x0FFF, 0xF7FF, 0x0001},
       {-2048, -1, 2047, 1}},
      {"signed 16 bit, slope 0.5",
       {16, 16, 1, "MONOCHROME2", "0.5", "10"},
       {0xFFFE, 0x8000, 0x7FFF, 20},
       {9, -16374, 16394, 20}},
      {"MONOCHROME1 is inverted", {8, 8, 0, "MONOCHROME1", "1", "0"}, {0, 55, 200, 255}, {255, 200, 55, 0}},
  };
  for (const Case& c : cases) {
    const auto path = folder / "encoded.dcm";
    write_encoded(path, c.encoding, c.stored);
    DicomSlice s = read_dicom_slice(path);
    EXPECT_EQ(s.hu, c.hu) << c.name;
  }
}

TEST(DicomSliceReader, DecodesJpegLosslessJpegLsAndRle) {
  if (!testing::tool_available("dcmcjpeg") || !testing::tool_available("dcmcjpls") ||
      !testing::tool_available("dcmcrle"))
    GTEST_SKIP() << "DCMTK command-line tools (dcmcjpeg, dcmcjpls, dcmcrle) are not installed";
  TemporaryFolder folder("slice-codecs");
  const Volume v = small_ct(Eigen::Matrix3d::Identity());
  const auto plain = write_ct_series(v, {}, folder.path()).files.at(2);
  const DicomSlice reference = read_dicom_slice(plain);
  for (const std::string tool : {"dcmcjpeg +e1", "dcmcjpls", "dcmcrle"}) {
    const auto compressed = folder / "compressed.dcm";
    auto run = testing::run_command(tool + " " + testing::quote(plain) + " " + testing::quote(compressed) + " 2>&1");
    ASSERT_EQ(run.exit_code, 0) << tool << ": " << run.output;
    auto syntax = testing::run_command("dcmdump -s +P 0002,0010 " + testing::quote(compressed));
    EXPECT_EQ(syntax.output.find("=LittleEndianExplicit"), std::string::npos) << tool << " did not compress";
    DicomSlice s = read_dicom_slice(compressed);
    EXPECT_EQ(s.hu, reference.hu) << tool;
  }
}

TEST(DicomSliceReader, RefusesWhatItCannotRead) {
  TemporaryFolder folder("slice-refusals");
  const auto good = write_ct_series(small_ct(Eigen::Matrix3d::Identity()), {}, folder / "series").files.at(0);
  auto modified = [&](const std::string& name, auto change) {
    DcmFileFormat file;
    EXPECT_TRUE(file.loadFile(good.c_str()).good());
    change(*file.getDataset());
    const auto path = folder / name;
    EXPECT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
    return path;
  };
  std::string reason;
  EXPECT_EQ(code_of_reading(
                modified("rgb.dcm", [](DcmDataset& d) { d.putAndInsertString(DCM_PhotometricInterpretation, "RGB"); }),
                &reason),
            ErrorCode::kUnsupportedSyntax);
  EXPECT_NE(reason.find("RGB"), std::string::npos) << reason;
  EXPECT_EQ(code_of_reading(
                modified("frames.dcm", [](DcmDataset& d) { d.putAndInsertString(DCM_NumberOfFrames, "2"); }), &reason),
            ErrorCode::kUnsupportedSyntax);
  EXPECT_NE(reason.find("multi-frame"), std::string::npos) << reason;
  EXPECT_EQ(
      code_of_reading(modified("no-ipp.dcm", [](DcmDataset& d) { d.findAndDeleteElement(DCM_ImagePositionPatient); }),
                      &reason),
      ErrorCode::kMissingAttribute);
  EXPECT_NE(reason.find("Image Position (Patient)"), std::string::npos) << reason;

  // JPEG 2000: a valid encapsulation with a fake codestream; DCMTK has no decoder for it.
  const auto j2k = folder / "j2k.dcm";
  testing::write_jpeg2000(good, j2k);
  EXPECT_EQ(code_of_reading(j2k, &reason), ErrorCode::kUnsupportedSyntax);
  EXPECT_NE(reason.find("JPEG 2000"), std::string::npos) << reason;

  const auto text = folder / "notes.txt";
  std::ofstream(text) << "not a DICOM file\n";
  EXPECT_EQ(code_of_reading(text), ErrorCode::kNotDicom);
  EXPECT_EQ(code_of_reading(folder / "absent.dcm"), ErrorCode::kFileNotFound);
}

}  // namespace
}  // namespace maxillo
