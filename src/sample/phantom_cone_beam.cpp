#include "sample/phantom_cone_beam.h"

#include <algorithm>
#include <cmath>

#include "core/parallel_slabs.h"

namespace maxillo::sample {
namespace {

constexpr double kFillingRadiusMm = 6;  // amalgam voxels this close belong to one filling
constexpr int kStreakRays = 12;         // bright rays around a filling (as many dark between)
constexpr double kStreakFadeMm = 12;    // the streaks' amplitude halves at this distance
constexpr double kStarvedBandMm = 2.5;  // half-width of the dark band between two fillings

double axial_radius(const Eigen::Vector3d& p, const ConeBeamFlavour& flavour) {
  return (p.head<2>() - flavour.field_centre_mm).norm();
}

// The centres of the fillings cut by slice k (world mm), from its amalgam voxels.
std::vector<Eigen::Vector3d> filling_centres(const PaintedGrid& grid, int k) {
  const VolumeGeometry& g = grid.geometry;
  std::vector<Eigen::Vector3d> sums;
  std::vector<int> counts;
  for (int j = 0; j < g.size.y(); ++j)
    for (int i = 0; i < g.size.x(); ++i) {
      if (grid.material[g.index(i, j, k)] != Material::kAmalgam) continue;
      const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
      size_t f = 0;
      while (f < sums.size() && (sums[f] / counts[f] - p).norm() > kFillingRadiusMm) ++f;
      if (f == sums.size()) {
        sums.push_back(Eigen::Vector3d::Zero());
        counts.push_back(0);
      }
      sums[f] += p;
      ++counts[f];
    }
  for (size_t f = 0; f < sums.size(); ++f) sums[f] /= counts[f];
  return sums;
}

double streak_at(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& fillings, double amplitude) {
  double value = 0;
  for (const auto& c : fillings) {
    const Eigen::Vector2d d = (p - c).head<2>();
    const double r = d.norm();
    value += amplitude * std::cos(kStreakRays * std::atan2(d.y(), d.x())) * kStreakFadeMm / (kStreakFadeMm + r);
  }
  for (size_t a = 0; a < fillings.size(); ++a)
    for (size_t b = a + 1; b < fillings.size(); ++b) {
      const Eigen::Vector2d from = fillings[a].head<2>(), along = fillings[b].head<2>() - from;
      const double t = std::clamp((p.head<2>() - from).dot(along) / along.squaredNorm(), 0.0, 1.0);
      const double off = (p.head<2>() - (from + t * along)).norm() / kStarvedBandMm;
      value -= 1.5 * amplitude * std::exp(-off * off);
    }
  return value;
}

}  // namespace

void add_cupping(std::vector<float>& hu, const VolumeGeometry& g, const ConeBeamFlavour& flavour) {
  for_each_slab(0, g.size.z(), [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          const double r = axial_radius(g.world(Eigen::Vector3d(i, j, k)), flavour) / flavour.field_radius_mm;
          const double kept = 1 - flavour.cupping * std::max(0.0, 1 - r * r);
          float& value = hu[g.index(i, j, k)];
          value = float((value + 1000) * kept - 1000);
        }
  });
}

void add_metal_streaks(std::vector<float>& hu, const PaintedGrid& grid, const ConeBeamFlavour& flavour) {
  const VolumeGeometry& g = grid.geometry;
  for_each_slab(0, g.size.z(), [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      const std::vector<Eigen::Vector3d> fillings = filling_centres(grid, k);
      if (fillings.empty()) continue;
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          const int64_t v = g.index(i, j, k);
          if (grid.material[v] == Material::kAmalgam) continue;  // the metal itself stays saturated
          hu[v] += float(streak_at(g.world(Eigen::Vector3d(i, j, k)), fillings, flavour.streak_hu));
        }
    }
  });
}

void to_cone_beam_grey(std::vector<float>& values, const VolumeGeometry& g, const ConeBeamFlavour& flavour) {
  for_each_slab(0, g.size.z(), [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          float& value = values[g.index(i, j, k)];
          value = flavour.reconstructs(g.world(Eigen::Vector3d(i, j, k)))
                      ? float(flavour.grey_of_air + flavour.grey_per_hu * (value + 1000))
                      : float(flavour.padding_grey);
        }
  });
}

VolumeGeometry cone_beam_grid(const ConeBeamFlavour& flavour, double spacing_mm) {
  const double r = flavour.field_radius_mm;
  const Eigen::Vector3d lo(flavour.field_centre_mm.x() - r, flavour.field_centre_mm.y() - r, flavour.field_bottom_mm);
  const Eigen::Vector3d extent(2 * r, 2 * r, flavour.field_top_mm - flavour.field_bottom_mm);
  VolumeGeometry g;
  g.spacing = Eigen::Vector3d::Constant(spacing_mm);
  for (int axis = 0; axis < 3; ++axis) g.size[axis] = int(std::floor(extent[axis] / spacing_mm)) + 1;
  g.origin = lo;
  return g;
}

}  // namespace maxillo::sample
