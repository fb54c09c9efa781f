#pragma once
// Non-DICOM volume files (MetaImage .mhd/.mha, NRRD .nrrd/.nhdr) read through ITK, to wrap
// research data sets as DICOM series (`maxillo convert`).
#include <filesystem>

#include "core/volume.h"

namespace maxillo {

struct VolumeFileOptions {
  // Added to every stored value to obtain HU (e.g. -1024 for data stored as HU + 1024).
  double hu_offset = 0;
};

// Reads a scalar 3D image. The geometry is the file's (ITK reads MetaImage/NRRD into the LPS
// frame: Offset/origin, ElementSpacing, TransformMatrix/space directions). Values are rounded
// to the nearest integer after adding hu_offset.
// Throws Error naming the path: FileNotFound; UnsupportedSyntax (unknown extension, not 3D,
// more than one component); BadValue (unreadable, or a value outside the int16 HU range).
Volume read_volume_file(const std::filesystem::path& path, const VolumeFileOptions& options = {});

}  // namespace maxillo
