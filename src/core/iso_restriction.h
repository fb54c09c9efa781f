#pragma once
// The rule by which a CT value is made to follow a mask at an iso-level, one voxel at a time:
// voxels inside the mask are raised to at least iso + 1, voxels outside lowered to at most
// iso - 1. The iso-surface of the result is then the mask's boundary, drawn through the CT's own
// sub-voxel values wherever the CT and the mask agree (imaging's restrict_to_mask makes such a
// volume; mesh's extract_region_surface applies the rule while it reads, without the copy).
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace maxillo {

class IsoRestriction {
 public:
  explicit IsoRestriction(double iso_hu)
      : inside_floor_(int(std::floor(iso_hu)) + 1), outside_ceiling_(int(std::ceil(iso_hu)) - 1) {}

  int16_t operator()(int16_t hu, bool inside) const {
    const int value = inside ? std::max(int(hu), inside_floor_) : std::min(int(hu), outside_ceiling_);
    return int16_t(std::clamp(value, -32768, 32767));
  }

 private:
  int inside_floor_;
  int outside_ceiling_;
};

}  // namespace maxillo
