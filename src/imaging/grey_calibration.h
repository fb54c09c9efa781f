#pragma once
// Grey values as Hounsfield units, from the scan itself. A CT's values are HU when its rescale
// is right; a cone-beam CT's are not (each scanner scales them its own way), and a volume
// converted without its offset (raw CT numbers, HU + 1024) is not either. Fixed HU thresholds
// then find no bone, or bone everywhere. Every head scan holds two tissues in bulk, air (outside
// the head, the airway, the sinuses) and soft tissue (brain, muscle, skin), so the two largest
// modes of its histogram name them: air is -1000 HU and soft tissue 40 HU, and the straight line
// through the two maps every grey value to HU (CT numbers are linear in attenuation).
#include <optional>
#include <string>

#include "core/volume.h"

namespace maxillo {

struct GreyCalibration {
  double air = -1000;           // the grey value of air
  double soft_tissue = 40;      // the grey value of soft tissue
  bool from_histogram = false;  // false: the scan had no two clear modes, the identity is used
  std::optional<int> padding;   // the value a scanner filled its unreconstructed corners with

  double to_hu(double grey) const { return -1000 + (grey - air) * 1040 / (soft_tissue - air); }
  double from_hu(double hu) const { return air + (hu + 1000) * (soft_tissue - air) / 1040; }
  // Whether the scan's values are HU already (within `tolerance_hu` at air and soft tissue).
  bool is_hounsfield(double tolerance_hu = 100) const;
  // "air at -1000, soft tissue at 40 (HU as stored)" or the grey values it found.
  std::string describe() const;
};

// The air and soft-tissue modes of the volume's histogram (see above). Deterministic.
GreyCalibration estimate_grey_calibration(const Volume& volume);

}  // namespace maxillo
