#pragma once
// The sample case on disk: the synthetic phantom written as a DICOM CT series plus its
// analytic landmarks, ready to be imported like a patient's scan.
#include <filesystem>

#include "ceph/landmark.h"
#include "dicom/dicom_series_writer.h"
#include "sample/phantom.h"

namespace maxillo::casework {

struct SampleCase {
  std::filesystem::path ct_folder;      // out/ct/slice0000.dcm ...
  std::filesystem::path markups_file;   // out/landmarks.mrk.json (3D Slicer markups, LPS)
  std::filesystem::path csv_file;       // out/landmarks.csv (label,x,y,z; LPS)
  std::filesystem::path dental_folder;  // out/dental/{upper,lower}.stl, truth.json (phantom_dental_scans.h)
  WrittenSeries series;
  LandmarkSet landmarks;
  VolumeGeometry geometry;
  PhantomSpec spec;  // what was drawn
};

// The phantom's Patient ID: the demo finds its case by it.
inline constexpr const char* kPhantomPatientId = "MAXILLO-PHANTOM-001";

// What `maxillo sample` makes.
struct SampleRequest {
  SkeletalClass skeletal_class = SkeletalClass::I;  // the designed head's class (a varied one draws its own)
  double spacing_mm = 1.0;
  std::string patient_id = kPhantomPatientId;
  // Anatomy, pose and noise drawn from the Patient ID (sample/phantom_variation.h): another
  // patient per ID. Without it, another ID is the same head under another name and UIDs.
  bool varied = false;
  bool cone_beam = false;  // the cone-beam flavour: grey values that are not HU, cupping, streaks, a cut field

  PhantomSpec phantom_spec() const;
  std::string series_description() const;  // "Phantom CT 1.00 mm, skeletal Class I", ...
};

// Patient, study and series attributes of the phantom's DICOM series.
// Another Patient ID makes another patient (and other UIDs), e.g. several cases for `maxillo nightly`.
SeriesMetadata phantom_series_metadata(const SampleRequest& request);

std::string_view name_of(SkeletalClass skeletal_class);  // "I", "II", "III"

// Generates the phantom and writes it under out_dir (created): ct/ replaced as a whole (never
// a mix of two runs' slices), landmarks.mrk.json and landmarks.csv (a landmark outside a
// cone-beam field is left out: the scan does not hold it), and dental/ (the arches' intraoral
// scans in scanners' frames, with the truth of their poses). Deterministic: the same request
// gives byte-identical files, UIDs included.
SampleCase write_sample_case(const SampleRequest& request, const std::filesystem::path& out_dir);
// The designed head of this class and spacing.
SampleCase write_sample_case(SkeletalClass skeletal_class, double spacing_mm, const std::filesystem::path& out_dir,
                             const std::string& patient_id = kPhantomPatientId);

}  // namespace maxillo::casework
