#pragma once
// The attributes the archive indexes, read from a DICOM Part 10 file held in memory.
// The import's bridge to DCMTK in the dicom module, the only module besides net that knows
// DCMTK: the struct holds plain strings and numbers, so nothing outside dicom_header.cpp sees it.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace maxillo {

struct InstanceHeader {
  std::string transfer_syntax_uid;  // from the file meta information (0002,0010)
  std::string sop_class_uid;
  std::string sop_instance_uid;
  // Patient: text decoded to UTF-8 when the file declares another character set.
  std::string patient_id;
  std::string patient_name;
  std::string birth_date;  // YYYYMMDD or empty
  std::string sex;         // M, F, O or empty
  // Study.
  std::string study_uid;
  std::string study_date;
  std::string study_time;
  std::string study_description;
  std::string accession_number;
  // Series.
  std::string series_uid;
  std::string modality;
  std::string series_description;
  std::optional<int> series_number;
  // Image.
  std::optional<int> instance_number;
  std::optional<int> rows;
  std::optional<int> columns;
  std::optional<double> pixel_spacing_row;     // mm between rows
  std::optional<double> pixel_spacing_column;  // mm between columns
  std::optional<double> slice_thickness;       // mm
  std::string image_position;                  // (0020,0032) as stored: x\y\z in mm, LPS
  std::string image_orientation;               // (0020,0037) as stored
};

// Parses bytes (a whole DICOM Part 10 file). `path` only names the file in errors.
// Throws Error with code NotDicom (no DICM prefix or unparseable), Truncated, MissingAttribute
// (SOP Instance/Class, Study, Series UID or Patient ID absent) or UnsupportedSyntax (a transfer
// syntax DCMTK has no decoder for, e.g. JPEG 2000).
InstanceHeader parse_instance_header(std::span<const std::byte> bytes, const std::filesystem::path& path);

// Silences DCMTK's own logging (our errors name the file once) and registers the decoders
// (JPEG, JPEG-LS, RLE) whose presence decides which transfer syntaxes are supported.
// Idempotent and thread-safe.
void initialise_dicom_toolkit();

}  // namespace maxillo
