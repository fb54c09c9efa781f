#pragma once
// Shared helpers of the DICOM codec's tests (and, through archive_fixture.h, the archive's):
// small CT series written by the real series writer.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "dicom/dicom_series_writer.h"
#include "support/temporary_folder.h"

namespace maxillo::testing {

inline Volume small_volume(int slices, int size = 16, int16_t base = 0) {
  Volume volume;
  volume.geometry.size = {size, size, slices};
  volume.geometry.spacing = {0.5, 0.5, 1.0};
  volume.hu.resize(size_t(volume.geometry.voxel_count()));
  for (size_t n = 0; n < volume.hu.size(); ++n) volume.hu[n] = int16_t(base + int(n % 3000) - 1000);
  return volume;
}

inline SeriesMetadata patient_metadata(const std::string& patient_id, const std::string& name = "Doe^Jane") {
  SeriesMetadata metadata;
  metadata.patient_id = patient_id;
  metadata.patient_name = name;
  metadata.patient_birth_date = "19800101";
  metadata.patient_sex = "F";
  metadata.study_date = "20240315";
  metadata.study_description = "CBCT skull";
  metadata.series_description = "axial";
  return metadata;
}

inline WrittenSeries write_series(const std::filesystem::path& folder, int slices, const std::string& patient_id = "P1",
                                  const std::string& name = "Doe^Jane") {
  return write_ct_series(small_volume(slices), patient_metadata(patient_id, name), folder);
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace maxillo::testing
