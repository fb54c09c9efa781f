#pragma once
// One DICOM image file read as one slice of a CT/MR series: the geometry attributes that place it
// in the patient frame and its pixels converted to Hounsfield units (rescale slope and intercept
// applied). DCMTK stays in the .cpp; this header only speaks maxillo types.
//
// Accepted: single-frame MONOCHROME1/2 images, 8 or 16 bits allocated, signed or unsigned, any
// BitsStored, in the uncompressed transfer syntaxes, deflate, JPEG (baseline, extended, lossless),
// JPEG-LS and RLE. Refused with Error(kUnsupportedSyntax): JPEG 2000 and other syntaxes without a
// decoder, colour images, multi-frame images. Refused with Error(kMissingAttribute): a slice
// without Image Position/Orientation (Patient), Pixel Spacing, Rows or Columns.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace maxillo {

struct DicomSlice {
  std::filesystem::path path;
  std::string series_instance_uid;
  std::string sop_instance_uid;
  int instance_number = 0;                    // 0 when absent
  Eigen::Vector3d position{0, 0, 0};          // Image Position (Patient): LPS mm of the first pixel's centre
  Eigen::Vector3d row_direction{1, 0, 0};     // IOP[0..2]: LPS unit vector along a row (column index grows)
  Eigen::Vector3d column_direction{0, 1, 0};  // IOP[3..5]: LPS unit vector down a column (row index grows)
  double row_spacing = 1;                     // mm between the centres of adjacent rows    (Pixel Spacing[0])
  double column_spacing = 1;                  // mm between the centres of adjacent columns (Pixel Spacing[1])
  int rows = 0;
  int columns = 0;
  double rescale_slope = 1;
  double rescale_intercept = 0;
  std::optional<double> gantry_tilt_degrees;  // Gantry/Detector Tilt (0018,1120) when present
  // rows*columns values, row-major (index = column + columns*row), HU rounded to the nearest
  // integer and clamped to int16. MONOCHROME1 is inverted before rescaling.
  std::vector<int16_t> hu;

  // Unit normal of the slice plane: row_direction x column_direction.
  Eigen::Vector3d normal() const { return row_direction.cross(column_direction); }
};

// Reads and decodes one file. Throws Error naming `path`: FileNotFound, NotDicom,
// MissingAttribute, UnsupportedSyntax, BadValue (e.g. pixel data shorter than rows*columns).
DicomSlice read_dicom_slice(const std::filesystem::path& path);

// The same, for a file already in memory; `path` only names it in errors.
DicomSlice decode_dicom_slice(std::span<const std::byte> bytes, const std::filesystem::path& path);

}  // namespace maxillo
