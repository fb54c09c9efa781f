#pragma once
// Writes a Volume as a DICOM CT series: one CT Image Storage file per k-slice, Explicit VR
// Little Endian, signed 16-bit pixels holding HU (rescale slope 1, intercept 0), with
// Image Position/Orientation (Patient) and Pixel Spacing taken from the volume geometry so
// that reading the series back reproduces the same LPS geometry.
// Used by `maxillo sample`, by converters of non-DICOM volumes, and by tests.
#include <filesystem>
#include <string>
#include <vector>

#include "core/volume.h"

namespace maxillo {

struct SeriesMetadata {
  // Patient module. Names are DICOM person names (Family^Given^Middle), UTF-8.
  std::string patient_name;
  std::string patient_id;
  std::string patient_birth_date;  // YYYYMMDD or empty
  std::string patient_sex;         // M, F, O or empty
  // Study and series modules; UIDs are generated when empty. When series_instance_uid is
  // given (at most 58 characters), the frame of reference and SOP Instance UIDs are numbered
  // under it (<series>.0, <series>.1 ...), so writing the same volume twice gives identical files.
  std::string study_instance_uid;
  std::string series_instance_uid;
  std::string study_date;  // YYYYMMDD
  std::string study_description;
  std::string series_description;
  int series_number = 1;
  std::string modality = "CT";
  std::string manufacturer = "maxillo";
  // Added after the first contract; defaults keep older callers unchanged.
  std::string study_time = "120000";  // HHMMSS
  std::string accession_number;
  double window_center = 300;  // HU; default: a bone window
  double window_width = 2000;  // HU
};

struct WrittenSeries {
  std::string study_instance_uid;
  std::string series_instance_uid;
  std::vector<std::filesystem::path> files;  // in slice order (k = 0, 1, ...)
};

// Creates `folder` if needed and writes slice k as folder/<prefix><k, 4 digits>.dcm.
// Throws Error(WriteFailed) naming the file that could not be written.
WrittenSeries write_ct_series(const Volume& volume, const SeriesMetadata& metadata, const std::filesystem::path& folder,
                              const std::string& prefix = "slice");

}  // namespace maxillo
