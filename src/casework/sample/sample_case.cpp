#include "casework/sample/sample_case.h"

#include <unistd.h>

#include <cstdio>

#include "ceph/landmark_io.h"
#include "casework/sample/phantom_dental_scans.h"
#include "core/error.h"
#include "core/parallel_slabs.h"
#include "core/log.h"
#include "core/progress.h"
#include "dicom/dicom_uid.h"
#include "sample/phantom_variation.h"

namespace maxillo::casework {
namespace {
namespace fs = std::filesystem;

// Writes the series into a fresh sibling folder, then swaps it in for `folder`, so that neither
// a half-written series nor stale slices of an earlier run (another spacing) stay behind.
WrittenSeries write_series_replacing(const Volume& ct, const SeriesMetadata& metadata, const fs::path& folder) {
  const std::string suffix = "." + std::to_string(::getpid());
  const fs::path fresh = folder.string() + ".new" + suffix, old = folder.string() + ".old" + suffix;
  fs::remove_all(fresh);
  WrittenSeries written = write_ct_series(ct, metadata, fresh);
  std::error_code error;
  if (fs::exists(folder)) fs::rename(folder, old, error);
  if (!error) fs::rename(fresh, folder, error);
  if (error) {
    fs::remove_all(fresh);
    throw Error(ErrorCode::kWriteFailed, folder.string(), "cannot replace the CT folder: " + error.message());
  }
  fs::remove_all(old, error);
  for (auto& file : written.files) file = folder / file.filename();
  return written;
}

}  // namespace

std::string_view name_of(SkeletalClass skeletal_class) {
  switch (skeletal_class) {
    case SkeletalClass::I: return "I";
    case SkeletalClass::II: return "II";
    case SkeletalClass::III: return "III";
  }
  return "?";
}

PhantomSpec SampleRequest::phantom_spec() const {
  const ScannerKind scanner = cone_beam ? ScannerKind::kConeBeam : ScannerKind::kCt;
  if (varied) return varied_phantom_spec(patient_id, scanner, spacing_mm);
  PhantomSpec spec = phantom_spec_for_class(skeletal_class);
  spec.spacing_mm = spacing_mm;
  if (cone_beam) spec.cone_beam = ConeBeamFlavour{};
  return spec;
}

std::string SampleRequest::series_description() const {
  char description[96];
  const std::string anatomy = varied ? "varied patient" : "skeletal Class " + std::string(name_of(skeletal_class));
  std::snprintf(description, sizeof description, "Phantom %s %.2f mm, %s", cone_beam ? "cone-beam CT" : "CT",
                spacing_mm, anatomy.c_str());
  return description;
}

SeriesMetadata phantom_series_metadata(const SampleRequest& request) {
  SeriesMetadata metadata;
  metadata.patient_name = "Phantom^Maxillo";
  metadata.patient_id = request.patient_id;
  metadata.patient_sex = "O";
  metadata.study_date = "20240521";
  metadata.study_description = "Synthetic craniofacial phantom";
  metadata.series_description = request.series_description();
  // UIDs derived from the description: the same phantom is the same scan, so regenerating it
  // re-imports as "already archived" instead of piling up copies.
  const std::string patient = request.patient_id == kPhantomPatientId ? "" : " of " + request.patient_id;
  metadata.study_instance_uid = derived_uid("maxillo phantom study" + patient);
  metadata.series_instance_uid = derived_uid("maxillo phantom series: " + metadata.series_description + patient);
  return metadata;
}

SampleCase write_sample_case(const SampleRequest& request, const fs::path& out_dir) {
  const PhantomSpec spec = request.phantom_spec();
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) throw Error(ErrorCode::kWriteFailed, out_dir.string(), "cannot create the folder: " + error.message());

  Progress progress("sample", 4);
  // The dental scans need only the design: traced beside the volume's voxelisation.
  Phantom phantom;
  PhantomDentalScans dental;
  run_concurrently({[&] { phantom = make_phantom(spec); }, [&] { dental = make_phantom_dental_scans(spec); }});
  progress.advance();
  const SeriesMetadata metadata = phantom_series_metadata(request);
  log::debug("sample: patient '", metadata.patient_name, "' id '", metadata.patient_id, "'");
  if (request.varied) log::debug("sample: ", describe_variation(spec));
  SampleCase sample;
  sample.ct_folder = out_dir / "ct";
  sample.series = write_series_replacing(phantom.ct, metadata, sample.ct_folder);
  progress.advance();
  sample.markups_file = out_dir / "landmarks.mrk.json";
  sample.csv_file = out_dir / "landmarks.csv";
  write_landmarks(sample.markups_file, phantom.landmarks);
  write_landmarks(sample.csv_file, phantom.landmarks);
  progress.advance();
  sample.dental_folder = out_dir / "dental";
  write_phantom_dental_scans(dental, sample.dental_folder);
  progress.advance();
  progress.finish();
  sample.landmarks = phantom.landmarks;
  sample.geometry = phantom.ct.geometry;
  sample.spec = spec;
  return sample;
}

SampleCase write_sample_case(SkeletalClass skeletal_class, double spacing_mm, const fs::path& out_dir,
                             const std::string& patient_id) {
  return write_sample_case(
      SampleRequest{.skeletal_class = skeletal_class, .spacing_mm = spacing_mm, .patient_id = patient_id}, out_dir);
}

}  // namespace maxillo::casework
