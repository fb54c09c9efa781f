#include "imaging/half_maximum_edge.h"

#include <algorithm>

#include "core/parallel_slabs.h"

namespace maxillo {
namespace {

bool on_boundary(const Mask& mask, size_t n, const std::array<size_t, 3>& step) {
  for (size_t s : step)
    if (!mask[n - s] || !mask[n + s]) return true;
  return false;
}

// Half-way between the brightest and the darkest value of the 3 x 3 x 3 block about n.
double half_way_level(const std::vector<int16_t>& values, size_t n, const std::array<size_t, 3>& step) {
  int brightest = -32768, darkest = 32767;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const size_t m = n + size_t(di) * step[0] + size_t(dj) * step[1] + size_t(dk) * step[2];
        brightest = std::max(brightest, int(values[m]));
        darkest = std::min(darkest, int(values[m]));
      }
  return 0.5 * (brightest + darkest);
}

}  // namespace

void trim_to_half_maximum(Mask& mask, const MaskGrid& grid, const std::vector<int16_t>& values) {
  if (grid.size[0] < 3 || grid.size[1] < 3 || grid.size[2] < 3) return;
  const std::array<size_t, 3> step{1, grid.size[0], grid.size[0] * grid.size[1]};
  const Mask before = mask;  // every decision reads the mask as thresholded: order does not matter
  for_each_slab(1, int(grid.size[2]) - 1, [&](int first, int last) {
    for (size_t k = size_t(first); k < size_t(last); ++k)
      for (size_t j = 1; j + 1 < grid.size[1]; ++j)
        for (size_t i = 1; i + 1 < grid.size[0]; ++i) {
          const size_t n = grid.index(i, j, k);
          if (before[n] && on_boundary(before, n, step) && values[n] < half_way_level(values, n, step)) mask[n] = 0;
        }
  });
}

}  // namespace maxillo
