#pragma once
// Between label volumes (core/volume.h, a label per voxel with its geometry) and the plain
// masks the morphology works on (mask_grid.h, one byte per voxel, spacing only).
#include <cstdint>
#include <initializer_list>

#include "core/volume.h"
#include "imaging/mask_grid.h"

namespace maxillo {

// The grid of a volume's voxels: its size and spacing (the morphology measures along the voxel
// axes, so the direction does not matter).
MaskGrid grid_of(const VolumeGeometry& geometry);

// 1 where the volume carries one of `labels`, 0 elsewhere.
Mask mask_of_labels(const LabelVolume& volume, std::initializer_list<uint8_t> labels);

}  // namespace maxillo
