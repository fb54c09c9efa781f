#include "planning/voxel_components.h"

namespace maxillo::planning {

VoxelComponents voxel_components(const std::vector<uint8_t>& mask, const Eigen::Vector3i& size) {
  const int64_t nx = size.x(), ny = size.y(), nz = size.z();
  const int64_t slice = nx * ny;
  VoxelComponents result;
  result.id.assign(mask.size(), 0);
  result.sizes.push_back(0);
  std::vector<int64_t> stack;
  for (int64_t start = 0; start < int64_t(mask.size()); ++start) {
    if (!mask[start] || result.id[start]) continue;
    const int32_t label = ++result.count;
    int64_t members = 0;
    result.id[start] = label;
    stack.push_back(start);
    while (!stack.empty()) {  // depth-first flood fill; an explicit stack, as regions are large
      const int64_t v = stack.back();
      stack.pop_back();
      ++members;
      const int64_t i = v % nx, j = (v / nx) % ny, k = v / slice;
      auto visit = [&](int64_t n) {
        if (mask[n] && !result.id[n]) {
          result.id[n] = label;
          stack.push_back(n);
        }
      };
      if (i > 0) visit(v - 1);
      if (i + 1 < nx) visit(v + 1);
      if (j > 0) visit(v - nx);
      if (j + 1 < ny) visit(v + nx);
      if (k > 0) visit(v - slice);
      if (k + 1 < nz) visit(v + slice);
    }
    result.sizes.push_back(members);
  }
  return result;
}

}  // namespace maxillo::planning
