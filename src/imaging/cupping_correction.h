#pragma once
// Cupping: a cone-beam scan darkens towards the scanner's axis (the beam hardens and scatters
// more along the long paths through the middle of the head), a smooth loss close to a parabola
// in the distance r from the axis. One threshold then cannot hold across the head: with 15 % lost
// on the axis and the grey scale set on the brain (grey_calibration.h), the soft tissue of the
// nose and lips at the field's rim reads 150-250 HU, as bright as a thin nasal spine.
//
// Soft tissue fills every ring of a head, so it shows the loss: the median grey value of the
// soft-tissue band, ring by ring about the grid's centre line (a cone-beam grid is the box of
// its reconstructed cylinder, centred on the axis), fitted by a + b r^2. Every value is then
// scaled about air's by the rim's level over its ring's, and the calibration estimated again.
// A calibrated CT (Hounsfield units as stored) has no cupping to speak of and is left alone.
#include "core/volume.h"
#include "imaging/grey_calibration.h"

namespace maxillo {

struct RadialCupping {
  double soft_at_axis = 1, soft_at_rim = 1;  // the fit's soft-tissue level above air (grey values)
  double rim_radius_mm = 0;                  // the outermost ring that held soft tissue

  // The share of the rim's level lost on the axis (0: none).
  double depth() const { return soft_at_rim > 0 ? 1 - soft_at_axis / soft_at_rim : 0; }
  bool significant() const { return depth() >= 0.02; }
};

// The loss measured in `volume` read through `grey` (deterministic; every other voxel sampled).
RadialCupping estimate_cupping(const Volume& volume, const GreyCalibration& grey);

// The volume with the loss undone: each value v becomes air + (v - air) * rim / level(r). The
// scanner's padding (GreyCalibration::padding) stays as it is.
Volume without_cupping(const Volume& volume, const GreyCalibration& grey, const RadialCupping& cupping);

}  // namespace maxillo
