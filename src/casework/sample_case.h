#pragma once
// The sample case on disk: the synthetic phantom written as a DICOM CT series plus its
// analytic landmarks, ready to be imported like a patient's scan.
#include <filesystem>

#include "archive/dicom_series_writer.h"
#include "ceph/landmark.h"
#include "sample/phantom.h"

namespace maxillo::casework {

struct SampleCase {
  std::filesystem::path ct_folder;     // out/ct/slice0000.dcm ...
  std::filesystem::path markups_file;  // out/landmarks.mrk.json (3D Slicer markups, LPS)
  std::filesystem::path csv_file;      // out/landmarks.csv (label,x,y,z; LPS)
  WrittenSeries series;
  LandmarkSet landmarks;
  VolumeGeometry geometry;
};

// The phantom's Patient ID: the demo finds its case by it.
inline constexpr const char* kPhantomPatientId = "MAXILLO-PHANTOM-001";

// Patient, study and series attributes of the phantom's DICOM series.
// Another Patient ID makes another patient (and other UIDs), e.g. several cases for `maxillo nightly`.
SeriesMetadata phantom_series_metadata(const PhantomSpec& spec, SkeletalClass skeletal_class,
                                       const std::string& patient_id = kPhantomPatientId);

std::string_view name_of(SkeletalClass skeletal_class);  // "I", "II", "III"

// Generates the phantom and writes it under out_dir (created): ct/ replaced as a whole (never
// a mix of two runs' slices), landmarks.mrk.json and landmarks.csv. Deterministic: the same
// class and spacing give byte-identical files, UIDs included.
SampleCase write_sample_case(SkeletalClass skeletal_class, double spacing_mm, const std::filesystem::path& out_dir,
                             const std::string& patient_id = kPhantomPatientId);

}  // namespace maxillo::casework
