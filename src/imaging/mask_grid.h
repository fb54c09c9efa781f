#pragma once
// Binary masks on a regular grid, as segmentation works on them: one byte per voxel (0 or 1),
// x fastest, index = i + size[0] * (j + size[1] * k). Plain C++, shared by the ITK bridge
// (itk_filters.h) and the plain mask algorithms (mask_components.h, distance_morphology.h).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace maxillo {

struct MaskGrid {
  std::array<size_t, 3> size{};
  std::array<double, 3> spacing{1, 1, 1};  // mm
  size_t voxel_count() const { return size[0] * size[1] * size[2]; }
  size_t index(size_t i, size_t j, size_t k) const { return i + size[0] * (j + size[1] * k); }
};

using Mask = std::vector<uint8_t>;  // 0 / 1 per voxel

}  // namespace maxillo
