#pragma once
// The cone-beam flavour of the phantom's CT (PhantomSpec::cone_beam, ConeBeamFlavour): what a
// cone-beam scanner does to the same head that a calibrated CT does not. Cupping and streaks act
// on the attenuation (in HU, before the noise); the grey mapping and the field's padding come last.
#include <vector>

#include "sample/phantom_voxelize.h"

namespace maxillo::sample {

// Darkens the attenuation towards the field's axis: (HU + 1000) scaled by
// 1 - cupping * (1 - (r / R)^2) at the distance r from the axis (R: the field's radius).
void add_cupping(std::vector<float>& hu, const VolumeGeometry& geometry, const ConeBeamFlavour& flavour);

// Streaks in every axial slice that holds amalgam: bright and dark rays alternating around each
// filling, fading with the distance, and a dark band between two fillings (the photon
// starvation along the line that crosses both). Slices are independent: thread count does not matter.
void add_metal_streaks(std::vector<float>& hu, const PaintedGrid& grid, const ConeBeamFlavour& flavour);

// HU to the scanner's grey values (grey_of_air + grey_per_hu * (HU + 1000)), and the padding
// value outside the reconstructed cylinder.
void to_cone_beam_grey(std::vector<float>& values, const VolumeGeometry& geometry, const ConeBeamFlavour& flavour);

// The grid a cone-beam scanner reconstructs: the bounding box of its cylinder.
VolumeGeometry cone_beam_grid(const ConeBeamFlavour& flavour, double spacing_mm);

}  // namespace maxillo::sample
