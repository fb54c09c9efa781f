// DICOM CT series writer: one CT Image Storage file per k-slice of a Volume.
// Attributes common to every slice are put once into a template dataset; each slice copies
// it and adds its own position, instance number, SOP Instance UID and pixels. 200 slices of
// 256x256 take ~0.1 s (mostly the file system).
#include "dicom/dicom_series_writer.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <cassert>
#include <cstdio>
#include <system_error>

#include "core/error.h"
#include "dicom/put_attribute.h"

namespace maxillo {
namespace {

std::string new_uid() {
  char buffer[100];
  return dcmGenerateUniqueIdentifier(buffer, SITE_INSTANCE_UID_ROOT);
}

// A Decimal String value holds at most 16 characters.
std::string decimal_string(double value) {
  char text[32];
  for (int precision = 10; precision > 1; --precision) {
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    if (std::string_view(text).size() <= 16) break;
  }
  return text;
}

std::string decimal_strings(std::initializer_list<double> values) {
  std::string joined;
  for (double value : values) {
    if (!joined.empty()) joined += '\\';
    joined += decimal_string(value);
  }
  return joined;
}

void put_patient_study_series(DcmDataset& d, const SeriesMetadata& m, const std::string& study_uid,
                              const std::string& series_uid, const std::string& frame_uid) {
  put(d, DCM_SpecificCharacterSet, "ISO_IR 192");  // UTF-8
  put(d, DCM_SOPClassUID, UID_CTImageStorage);
  put(d, DCM_ImageType, "ORIGINAL\\PRIMARY\\AXIAL");
  put(d, DCM_PatientName, m.patient_name);
  put(d, DCM_PatientID, m.patient_id);
  put(d, DCM_PatientBirthDate, m.patient_birth_date);
  put(d, DCM_PatientSex, m.patient_sex);
  put(d, DCM_StudyInstanceUID, study_uid);
  put(d, DCM_StudyDate, m.study_date);
  put(d, DCM_StudyTime, m.study_time);
  put(d, DCM_StudyDescription, m.study_description);
  put(d, DCM_AccessionNumber, m.accession_number);
  put(d, DCM_ReferringPhysicianName, "");
  put(d, DCM_StudyID, "1");
  put(d, DCM_SeriesInstanceUID, series_uid);
  put(d, DCM_SeriesDescription, m.series_description);
  put(d, DCM_SeriesNumber, std::to_string(m.series_number));
  put(d, DCM_Modality, m.modality);
  put(d, DCM_Manufacturer, m.manufacturer);
  put(d, DCM_FrameOfReferenceUID, frame_uid);
  put(d, DCM_PositionReferenceIndicator, "");
  put(d, DCM_KVP, "");
  put(d, DCM_AcquisitionNumber, "1");
}

void put_image_geometry(DcmDataset& d, const VolumeGeometry& g) {
  const Eigen::Matrix3d& axes = g.direction;
  put(d, DCM_ImageOrientationPatient,
      decimal_strings({axes(0, 0), axes(1, 0), axes(2, 0), axes(0, 1), axes(1, 1), axes(2, 1)}));
  // Pixel Spacing is (between rows, between columns) = (j spacing, i spacing).
  put(d, DCM_PixelSpacing, decimal_strings({g.spacing.y(), g.spacing.x()}));
  put(d, DCM_SliceThickness, decimal_string(g.spacing.z()));
  put(d, DCM_SpacingBetweenSlices, decimal_string(g.spacing.z()));
}

void put_pixel_description(DcmDataset& d, const VolumeGeometry& g, const SeriesMetadata& m) {
  d.putAndInsertUint16(DCM_SamplesPerPixel, 1);
  put(d, DCM_PhotometricInterpretation, "MONOCHROME2");
  d.putAndInsertUint16(DCM_Rows, static_cast<Uint16>(g.size.y()));
  d.putAndInsertUint16(DCM_Columns, static_cast<Uint16>(g.size.x()));
  d.putAndInsertUint16(DCM_BitsAllocated, 16);
  d.putAndInsertUint16(DCM_BitsStored, 16);
  d.putAndInsertUint16(DCM_HighBit, 15);
  d.putAndInsertUint16(DCM_PixelRepresentation, 1);  // signed
  put(d, DCM_RescaleIntercept, "0");
  put(d, DCM_RescaleSlope, "1");
  put(d, DCM_RescaleType, "HU");
  put(d, DCM_WindowCenter, decimal_string(m.window_center));
  put(d, DCM_WindowWidth, decimal_string(m.window_width));
}

std::filesystem::path slice_path(const std::filesystem::path& folder, const std::string& prefix, int k) {
  char number[16];
  std::snprintf(number, sizeof number, "%04d", k);
  return folder / (prefix + number + ".dcm");
}

void write_slice(const DcmDataset& common, const Volume& volume, int k, const std::string& sop_uid,
                 const std::filesystem::path& path) {
  const VolumeGeometry& g = volume.geometry;
  DcmFileFormat file(const_cast<DcmDataset*>(&common), OFTrue);  // deep copy of the template
  DcmDataset& d = *file.getDataset();
  Eigen::Vector3d position = g.origin + g.direction.col(2) * (g.spacing.z() * k);
  put(d, DCM_SOPInstanceUID, sop_uid);
  put(d, DCM_InstanceNumber, std::to_string(k + 1));
  put(d, DCM_ImagePositionPatient, decimal_strings({position.x(), position.y(), position.z()}));
  put(d, DCM_SliceLocation, decimal_string(position.dot(g.direction.col(2))));
  const size_t slice_voxels = size_t(g.size.x()) * g.size.y();
  const int16_t* pixels = volume.hu.data() + slice_voxels * k;
  // OW pixel data: the signed HU values travel as their 16-bit patterns.
  d.putAndInsertUint16Array(DCM_PixelData, reinterpret_cast<const Uint16*>(pixels),
                            static_cast<unsigned long>(slice_voxels));
  OFCondition status = file.saveFile(path.c_str(), EXS_LittleEndianExplicit);
  if (status.bad()) throw Error(ErrorCode::kWriteFailed, path.string(), status.text());
}

}  // namespace

WrittenSeries write_ct_series(const Volume& volume, const SeriesMetadata& metadata, const std::filesystem::path& folder,
                              const std::string& prefix) {
  const VolumeGeometry& g = volume.geometry;
  assert(g.size.minCoeff() > 0 && "write_ct_series needs a non-empty volume");
  assert(volume.hu.size() == size_t(g.voxel_count()) && "volume.hu must hold size.x*size.y*size.z values");
  assert(g.size.x() <= 65535 && g.size.y() <= 65535 && "DICOM rows/columns are 16-bit");

  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw Error(ErrorCode::kWriteFailed, folder.string(), error.message());

  WrittenSeries written;
  written.study_instance_uid = metadata.study_instance_uid.empty() ? new_uid() : metadata.study_instance_uid;
  written.series_instance_uid = metadata.series_instance_uid.empty() ? new_uid() : metadata.series_instance_uid;

  // A caller that names the series gets reproducible files: the frame of reference and the
  // instances are numbered under its UID. Otherwise every UID is new.
  const bool named_series = !metadata.series_instance_uid.empty();
  auto instance_uid = [&](int number) {
    return named_series ? written.series_instance_uid + "." + std::to_string(number) : new_uid();
  };

  DcmDataset common;
  put_patient_study_series(common, metadata, written.study_instance_uid, written.series_instance_uid, instance_uid(0));
  put_image_geometry(common, g);
  put_pixel_description(common, g, metadata);

  for (int k = 0; k < g.size.z(); ++k) {
    auto path = slice_path(folder, prefix, k);
    write_slice(common, volume, k, instance_uid(k + 1), path);
    written.files.push_back(std::move(path));
  }
  return written;
}

}  // namespace maxillo
