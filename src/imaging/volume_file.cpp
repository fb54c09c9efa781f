// MetaImage/NRRD -> Volume: ITK reads (itk_volume_io.cpp), this file converts to HU.
#include "imaging/volume_file.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "imaging/itk_filters.h"

namespace maxillo {

Volume read_volume_file(const std::filesystem::path& path, const VolumeFileOptions& options) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw Error(ErrorCode::kFileNotFound, path.string(), "no such file");
  itk_filters::RawVolume raw = itk_filters::read_scalar_volume(path.string());
  Volume volume;
  VolumeGeometry& g = volume.geometry;
  for (int a = 0; a < 3; ++a) {
    g.size[a] = int(raw.grid.size[a]);
    g.spacing[a] = raw.grid.spacing[a];
    g.origin[a] = raw.origin[a];
    for (int b = 0; b < 3; ++b) g.direction(a, b) = raw.direction[3 * a + b];
  }
  volume.hu.resize(raw.values.size());
  for (size_t n = 0; n < raw.values.size(); ++n) {
    double hu = std::round(double(raw.values[n]) + options.hu_offset);
    if (!(hu >= -32768 && hu <= 32767)) {
      std::ostringstream reason;
      reason << "value " << raw.values[n] << " + offset " << options.hu_offset << " at voxel " << n
             << " is outside the int16 HU range";
      throw Error(ErrorCode::kBadValue, path.string(), reason.str());
    }
    volume.hu[n] = int16_t(hu);
  }
  return volume;
}

}  // namespace maxillo
