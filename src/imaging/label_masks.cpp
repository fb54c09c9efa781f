#include "imaging/label_masks.h"

#include <algorithm>

namespace maxillo {

MaskGrid grid_of(const VolumeGeometry& geometry) {
  MaskGrid grid;
  for (int a = 0; a < 3; ++a) {
    grid.size[size_t(a)] = size_t(geometry.size[a]);
    grid.spacing[size_t(a)] = geometry.spacing[a];
  }
  return grid;
}

Mask mask_of_labels(const LabelVolume& volume, std::initializer_list<uint8_t> labels) {
  Mask mask(volume.labels.size());
  for (size_t n = 0; n < mask.size(); ++n)
    mask[n] = std::find(labels.begin(), labels.end(), volume.labels[n]) != labels.end() ? 1 : 0;
  return mask;
}

}  // namespace maxillo
