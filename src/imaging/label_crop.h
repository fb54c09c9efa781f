#pragma once
// The part of a volume that holds some labels: a small region (the teeth) traced as a surface
// from a head-sized volume costs seconds on the whole grid and milliseconds on its box.
#include <cstdint>
#include <initializer_list>
#include <string>

#include "core/volume.h"

namespace maxillo {

// Voxel indices [lo, hi] along each axis, both ends included.
struct VoxelBox {
  Eigen::Vector3i lo, hi;
};

// The box of the voxels labelled with any of `labels`, `margin` voxels wider on each side
// (within the volume). Error(kProcessing, subject) when no voxel carries one of the labels.
VoxelBox box_of_labels(const LabelVolume& volume, std::initializer_list<uint8_t> labels, int margin,
                       const std::string& subject);

// The box's voxels as a volume of their own, placed where they lie.
LabelVolume cropped(const LabelVolume& volume, const VoxelBox& box);
Volume cropped(const Volume& volume, const VoxelBox& box);

}  // namespace maxillo
