#include "sample/phantom_voxelize.h"

#include "core/parallel_slabs.h"
#include "sample/phantom_cone_beam.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace maxillo::sample {
namespace {

void paint_part(const Part& part, PaintedGrid& grid) {
  const VolumeGeometry& g = grid.geometry;
  Eigen::Vector3d lo = g.continuous_index(part.box.lo), hi = g.continuous_index(part.box.hi);
  Eigen::Vector3i first, last;
  for (int axis = 0; axis < 3; ++axis) {
    first[axis] = std::max(0, int(std::ceil(std::min(lo[axis], hi[axis]))));
    last[axis] = std::min(g.size[axis] - 1, int(std::floor(std::max(lo[axis], hi[axis]))));
    if (first[axis] > last[axis]) return;
  }
  for_each_slab(first.z(), last.z() + 1, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = first.y(); j <= last.y(); ++j)
        for (int i = first.x(); i <= last.x(); ++i) {
          int64_t index = g.index(i, j, k);
          if (!(part.overwrites & mask_of(Tissue(grid.tissue[index])))) continue;
          if (!part.inside(g.world(Eigen::Vector3d(i, j, k)))) continue;
          grid.tissue[index] = uint8_t(part.tissue);
          grid.material[index] = part.material;
        }
  });
}

// City-block distance (in voxels, capped at 255) from each bone voxel to the nearest non-bone voxel.
// The grid's border is no surface: bone cut by a small field (a cone-beam scan's) goes on beyond it.
std::vector<uint8_t> bone_depth(const PaintedGrid& grid) {
  const Eigen::Vector3i n = grid.geometry.size;
  std::vector<uint8_t> depth(grid.material.size());
  for (size_t v = 0; v < depth.size(); ++v) depth[v] = grid.material[v] == Material::kBone ? 255 : 0;
  auto relax = [&](int64_t v, int64_t w) { depth[v] = std::min<int>(depth[v], depth[w] + 1); };
  const int64_t sx = 1, sy = n.x(), sz = int64_t(n.x()) * n.y();
  for (int k = 0; k < n.z(); ++k)  // forward pass
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        int64_t v = grid.geometry.index(i, j, k);
        if (!depth[v]) continue;
        if (i > 0) relax(v, v - sx);
        if (j > 0) relax(v, v - sy);
        if (k > 0) relax(v, v - sz);
      }
  for (int k = n.z() - 1; k >= 0; --k)  // backward pass
    for (int j = n.y() - 1; j >= 0; --j)
      for (int i = n.x() - 1; i >= 0; --i) {
        int64_t v = grid.geometry.index(i, j, k);
        if (!depth[v]) continue;
        if (i < n.x() - 1) relax(v, v + sx);
        if (j < n.y() - 1) relax(v, v + sy);
        if (k < n.z() - 1) relax(v, v + sz);
      }
  return depth;
}

float material_hu(Material m) {
  switch (m) {
    case Material::kAir: return -1000;
    case Material::kFat: return -90;
    case Material::kSoft: return 40;
    case Material::kBrain: return 35;
    case Material::kVitreous: return 10;
    case Material::kBone: return 450;  // cancellous; cortical decided by depth
    case Material::kEnamel: return 2800;
    case Material::kDentine: return 1900;
    case Material::kHeadRest: return 60;
    case Material::kTable: return 150;
    case Material::kAmalgam: return 20000;  // far beyond the scale: saturated (3071) after blur and cupping
  }
  return 0;
}
constexpr float kCorticalHu = 1500;
constexpr double kCorticalThickness = 2;  // mm

// [1 2 1]/4 along one axis (edges repeat), in parallel over z slabs (or y slabs for z).
void blur_axis(std::vector<float>& values, const VolumeGeometry& g, int axis) {
  const Eigen::Vector3i n = g.size;
  const int64_t stride = axis == 0 ? 1 : axis == 1 ? n.x() : int64_t(n.x()) * n.y();
  std::vector<float> out(values.size());
  auto line = [&](int i, int j, int k) {
    int64_t v = g.index(i, j, k);
    int c = axis == 0 ? i : axis == 1 ? j : k;
    float left = c > 0 ? values[v - stride] : values[v];
    float right = c < n[axis] - 1 ? values[v + stride] : values[v];
    out[v] = 0.25f * left + 0.5f * values[v] + 0.25f * right;
  };
  for_each_slab(0, n.z(), [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < n.y(); ++j)
        for (int i = 0; i < n.x(); ++i) line(i, j, k);
  });
  values.swap(out);
}

// Adds N(0, sigma^2) noise; each z slice draws from its own generator seeded from (seed, k),
// so the result does not depend on the number of threads.
void add_noise(std::vector<float>& values, const VolumeGeometry& g, double sigma, uint32_t seed) {
  const int64_t slice = int64_t(g.size.x()) * g.size.y();
  for_each_slab(0, g.size.z(), [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      std::mt19937_64 random(uint64_t(seed) * 0x9E3779B97F4A7C15ull + uint64_t(k));
      const double to_unit = 1.0 / 18446744073709551616.0;        // 2^-64
      for (int64_t v = k * slice; v < (k + 1) * slice; v += 2) {  // Box-Muller: two normals per draw
        double u1 = (double(random()) + 1) * to_unit, u2 = double(random()) * to_unit;
        double r = sigma * std::sqrt(-2 * std::log(u1));
        values[v] += float(r * std::cos(2 * M_PI * u2));
        if (v + 1 < (k + 1) * slice) values[v + 1] += float(r * std::sin(2 * M_PI * u2));
      }
    }
  });
}

}  // namespace

PaintedGrid paint_parts(const PartList& parts, const VolumeGeometry& geometry) {
  PaintedGrid grid{geometry, std::vector<uint8_t>(geometry.voxel_count(), uint8_t(Tissue::kAir)),
                   std::vector<Material>(geometry.voxel_count(), Material::kAir)};
  for (const Part& part : parts) paint_part(part, grid);
  return grid;
}

Volume compute_ct(const PaintedGrid& grid, const PhantomSpec& spec) {
  const std::vector<uint8_t> depth = bone_depth(grid);
  const int cortical_voxels = std::max(1, int(std::lround(kCorticalThickness / spec.spacing_mm)));
  std::vector<float> hu(grid.material.size());
  for (size_t v = 0; v < hu.size(); ++v)
    hu[v] = grid.material[v] == Material::kBone && depth[v] <= cortical_voxels ? kCorticalHu
                                                                               : material_hu(grid.material[v]);
  if (spec.partial_volume == PartialVolume::Blurred)
    for (int axis = 0; axis < 3; ++axis) blur_axis(hu, grid.geometry, axis);

  if (spec.cone_beam) {
    add_cupping(hu, grid.geometry, *spec.cone_beam);
    if (spec.cone_beam->metal_fillings) add_metal_streaks(hu, grid, *spec.cone_beam);
  }
  if (spec.noise_sigma_hu > 0) add_noise(hu, grid.geometry, spec.noise_sigma_hu, spec.noise_seed);
  for (float& value : hu) value = std::clamp(value, -1024.0f, 3071.0f);  // the scanner's range
  if (spec.cone_beam) to_cone_beam_grey(hu, grid.geometry, *spec.cone_beam);
  Volume ct{grid.geometry, std::vector<int16_t>(hu.size())};
  for (size_t v = 0; v < hu.size(); ++v) ct.hu[v] = int16_t(std::clamp(std::lround(hu[v]), -32768L, 32767L));
  return ct;
}

}  // namespace maxillo::sample
