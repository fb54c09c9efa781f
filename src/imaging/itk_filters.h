#pragma once
// Internal to src/imaging: the ITK operations segmentation and volume files need, on plain
// buffers. The ITK translation units (itk_filters.cpp, itk_volume_io.cpp) include this header
// and ITK only, never Eigen: ITK 5.2 bundles its own Eigen 3.3 whose include guards collide
// with the system Eigen 3.4 that maxillo uses.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace maxillo::itk_filters {

// A regular grid, x fastest: index = i + size[0] * (j + size[1] * k).
struct Grid {
  std::array<size_t, 3> size{};
  std::array<double, 3> spacing{1, 1, 1};  // mm
};
using Mask = std::vector<uint8_t>;  // 0 / 1 per voxel

// 6-connected components.
Mask largest_component(const Mask& mask, const Grid& grid);
Mask components_of_at_least(const Mask& mask, const Grid& grid, int64_t min_voxels);
// Ball-shaped structuring element of radius_mm (at least one voxel along each axis).
Mask opened(const Mask& mask, const Grid& grid, double radius_mm);
Mask dilated(const Mask& mask, const Grid& grid, double radius_mm);
// Background regions not connected to the border of the grid become foreground.
Mask holes_filled(const Mask& mask, const Grid& grid);

struct RawVolume {
  Grid grid;
  std::array<double, 3> origin{};
  std::array<double, 9> direction{};  // row-major 3x3, columns = axes of i, j, k
  std::vector<float> values;
};
// MetaImage or NRRD scalar 3D image; throws maxillo::Error naming `path`.
RawVolume read_scalar_volume(const std::string& path);

}  // namespace maxillo::itk_filters
