// Voxel-wise helpers of segmentation.h that need no ITK (kept out of segmentation.cpp so they
// compile in a second instead of a minute).
#include <algorithm>
#include <cassert>
#include <cmath>

#include "imaging/segmentation.h"

namespace maxillo {

LabelVolume select_labels(const LabelVolume& labels, uint8_t first, uint8_t last) {
  LabelVolume out{labels.geometry, std::vector<uint8_t>(labels.labels.size())};
  for (size_t n = 0; n < labels.labels.size(); ++n)
    out.labels[n] = (labels.labels[n] >= first && labels.labels[n] <= last) ? 1 : 0;
  return out;
}

Volume restrict_to_mask(const Volume& volume, const LabelVolume& mask, double iso_hu) {
  assert(mask.labels.size() == volume.hu.size() && "mask and volume must share the grid");
  const int inside_floor = int(std::floor(iso_hu)) + 1;
  const int outside_ceiling = int(std::ceil(iso_hu)) - 1;
  Volume out{volume.geometry, std::vector<int16_t>(volume.hu.size())};
  for (size_t n = 0; n < volume.hu.size(); ++n) {
    int value = volume.hu[n];
    value = mask.labels[n] ? std::max(value, inside_floor) : std::min(value, outside_ceiling);
    out.hu[n] = int16_t(std::clamp(value, -32768, 32767));
  }
  return out;
}

}  // namespace maxillo
