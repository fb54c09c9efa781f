#pragma once
// DICOM slices of one series -> one Volume in Hounsfield units on a regular grid in patient LPS.
// Pure C++/Eigen: no ITK, no DCMTK here (slices come from dicom/dicom_slice_reader.h).
//
// Geometry of the result (see core/volume.h):
//   direction columns = (row direction, column direction, slice normal = row x column), so the
//   direction matrix is always a proper rotation; i runs along a row (DICOM column index),
//   j down a column (DICOM row index), k along the normal in increasing position.
//   spacing = (Pixel Spacing[1], Pixel Spacing[0], slice spacing), origin = first slice's IPP.
//
// Checks, each refused with Error(kInconsistentSeries, <offending file>, <reason>):
//   fewer than 3 slices; different Series Instance UIDs; different orientation, rows/columns or
//   pixel spacing; two slices at the same position (< 1% of the spacing apart); slice positions
//   not on a line along the normal (gantry tilt: the reason gives the tilt angle; tilted series
//   are refused, not resampled, because a sheared grid would mislead every later measurement);
//   a gap larger than 1.5x the median gap (missing slices: the reason names the files either side).
// Slice spacing handling:
//   every slice within 5% of a spacing of the uniform line fitted through first and last slice:
//     used as is (jitter tolerated), spacing = (last - first) / (n - 1);
//   otherwise (e.g. 1 mm and 1.25 mm gaps mixed, no gap > 1.5x median): resampled to a uniform
//     grid with the median gap by linear interpolation along the normal between the two
//     neighbouring slices (HU rounded to integers).
#include <filesystem>
#include <vector>

#include "core/volume.h"
#include "dicom/dicom_slice_reader.h"

namespace maxillo {

enum class SliceSpacing { Uniform, Resampled };

struct AssemblyReport {
  int input_slices = 0;
  SliceSpacing spacing = SliceSpacing::Uniform;
  double max_deviation_mm = 0;  // largest distance of a slice from the uniform line along the normal
};

// Takes the slices by value (their pixels move into the volume). Throws Error as listed above.
Volume assemble_volume(std::vector<DicomSlice> slices, AssemblyReport* report = nullptr);

// Reads each file with read_dicom_slice (progress bar on a terminal), then assemble_volume.
// A file that cannot be read stops the whole series: its Error names the file.
Volume load_series_volume(const std::vector<std::filesystem::path>& files, AssemblyReport* report = nullptr);

}  // namespace maxillo
