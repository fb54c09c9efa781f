// Voxel-wise helpers of segmentation.h that need no ITK (kept out of segmentation.cpp so they
// compile in a second instead of a minute).
#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/iso_restriction.h"
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
  const IsoRestriction restrict_at(iso_hu);
  Volume out{volume.geometry, std::vector<int16_t>(volume.hu.size())};
  for (size_t n = 0; n < volume.hu.size(); ++n) out.hu[n] = restrict_at(volume.hu[n], mask.labels[n] != 0);
  return out;
}

}  // namespace maxillo
