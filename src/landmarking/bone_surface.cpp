#include "landmarking/bone_surface.h"

#include <cmath>

#include "core/parallel_slabs.h"
#include "core/volume_resample.h"

namespace maxillo::landmarking {
namespace {

constexpr int kSlabs = 16;

// The scan's bounding box in LPS (its eight corners).
void scan_box(const VolumeGeometry& g, Eigen::Vector3d& lo, Eigen::Vector3d& hi) {
  lo.setConstant(1e30);
  hi.setConstant(-1e30);
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d ijk((corner & 1) ? g.size.x() - 1 : 0, (corner & 2) ? g.size.y() - 1 : 0,
                              (corner & 4) ? g.size.z() - 1 : 0);
    const Eigen::Vector3d p = g.world(ijk);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}

}  // namespace

BoneSurface sample_bone_surface(const Volume& ct, double bone_grey, double spacing_mm) {
  Eigen::Vector3d lo, hi;
  scan_box(ct.geometry, lo, hi);
  MaskGrid grid;
  grid.spacing = {spacing_mm, spacing_mm, spacing_mm};
  for (int a = 0; a < 3; ++a) grid.size[size_t(a)] = size_t(std::floor((hi[a] - lo[a]) / spacing_mm)) + 1;
  auto centre_of = [&](size_t i, size_t j, size_t k) {
    return Eigen::Vector3d(lo.x() + double(i) * spacing_mm, lo.y() + double(j) * spacing_mm,
                           lo.z() + double(k) * spacing_mm);
  };
  Mask bone(grid.voxel_count(), 0);
  for_each_slab(0, int(grid.size[2]), [&](int first, int last) {
    for (size_t k = size_t(first); k < size_t(last); ++k)
      for (size_t j = 0; j < grid.size[1]; ++j)
        for (size_t i = 0; i < grid.size[0]; ++i)
          bone[grid.index(i, j, k)] = sample_trilinear(ct, centre_of(i, j, k), -1e9) >= bone_grey;
  });
  // Surface voxels: bone with a 6-neighbour that is not bone. Sums per fixed slab, joined in order.
  Mask surface(grid.voxel_count(), 0);
  struct Sums {
    Eigen::Vector3d centre{0, 0, 0};
    Eigen::Vector3d lo{1e30, 1e30, 1e30}, hi{-1e30, -1e30, -1e30};
    int64_t count = 0;
  };
  std::vector<Sums> parts(kSlabs);
  for_each_part(kSlabs, [&](int part) {
    const PartRange slices = part_range(int64_t(grid.size[2]), part, kSlabs);
    Sums& sums = parts[size_t(part)];
    for (size_t k = size_t(slices.begin); k < size_t(slices.end); ++k)
      for (size_t j = 0; j < grid.size[1]; ++j)
        for (size_t i = 0; i < grid.size[0]; ++i) {
          if (!bone[grid.index(i, j, k)]) continue;
          const Eigen::Vector3d p = centre_of(i, j, k);
          sums.centre += p;
          sums.lo = sums.lo.cwiseMin(p);
          sums.hi = sums.hi.cwiseMax(p);
          ++sums.count;
          const bool inner = i > 0 && j > 0 && k > 0 && i + 1 < grid.size[0] && j + 1 < grid.size[1] &&
                             k + 1 < grid.size[2] && bone[grid.index(i - 1, j, k)] && bone[grid.index(i + 1, j, k)] &&
                             bone[grid.index(i, j - 1, k)] && bone[grid.index(i, j + 1, k)] &&
                             bone[grid.index(i, j, k - 1)] && bone[grid.index(i, j, k + 1)];
          surface[grid.index(i, j, k)] = !inner;
        }
  });
  BoneSurface result;
  int64_t count = 0;
  for (const auto& part : parts) {
    result.bone_centre += part.centre;
    result.lo = count ? result.lo.cwiseMin(part.lo) : part.lo;
    result.hi = count ? result.hi.cwiseMax(part.hi) : part.hi;
    count += part.count;
  }
  if (count == 0) return result;
  result.bone_centre /= double(count);
  result.bone_cm3 = double(count) * std::pow(spacing_mm, 3) / 1000;
  for (size_t k = 0; k < grid.size[2]; ++k)
    for (size_t j = 0; j < grid.size[1]; ++j)
      for (size_t i = 0; i < grid.size[0]; ++i)
        if (surface[grid.index(i, j, k)]) result.points.push_back(centre_of(i, j, k));
  result.distance = std::make_unique<SurfaceDistance>(surface, grid, lo);
  return result;
}

}  // namespace maxillo::landmarking
