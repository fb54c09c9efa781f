#pragma once
// Internal to src/imaging: the ITK operations volume files and registration need, on plain
// buffers. The ITK translation units (itk_volume_io.cpp, itk_registration.cpp) include this header
// and ITK only, never Eigen: ITK 5.2 bundles its own Eigen 3.3 whose include guards collide
// with the system Eigen 3.4 that maxillo uses.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "imaging/mask_grid.h"

namespace maxillo::itk_filters {

// A regular grid, x fastest: index = i + size[0] * (j + size[1] * k).
using Grid = MaskGrid;
using maxillo::Mask;

struct RawVolume {
  Grid grid;
  std::array<double, 3> origin{};
  std::array<double, 9> direction{};  // row-major 3x3, columns = axes of i, j, k
  std::vector<float> values;
};
// MetaImage or NRRD scalar 3D image; throws maxillo::Error naming `path`.
RawVolume read_scalar_volume(const std::string& path);

}  // namespace maxillo::itk_filters
