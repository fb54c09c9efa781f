#pragma once
// Closed test surfaces with known geometry, extracted (no smoothing, no decimation) from a fine
// volume whose HU falls linearly through 0 on the wanted surface, so the vertices lie on it to
// within a few hundredths of a millimetre.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "core/volume.h"
#include "mesh/surface_extraction.h"

namespace maxillo::validation::test {

// `inside_mm(p)`: positive inside, negative outside, ~ the distance to the surface near it.
// The volume is the cube [-half_extent, half_extent]^3 sampled every `spacing` mm.
inline TriangleMesh implicit_surface(const std::function<double(const Eigen::Vector3d&)>& inside_mm,
                                     double half_extent, double spacing = 1.0) {
  Volume v;
  const int n = int(std::ceil(2 * half_extent / spacing)) + 1;
  v.geometry.size = Eigen::Vector3i::Constant(n);
  v.geometry.spacing = Eigen::Vector3d::Constant(spacing);
  v.geometry.origin = Eigen::Vector3d::Constant(-(n - 1) * spacing / 2);
  v.hu.resize(size_t(v.geometry.voxel_count()));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        v.hu[size_t(v.geometry.index(i, j, k))] =
            int16_t(std::lround(std::clamp(100.0 * inside_mm(v.geometry.world(Eigen::Vector3d(i, j, k))), -3e4, 3e4)));
  SurfaceOptions options;
  options.smoothing_iterations = 0;
  return extract_surface(v, 0, options);
}

inline TriangleMesh sphere_surface(double radius, double spacing = 1.0) {
  return implicit_surface([radius](const Eigen::Vector3d& p) { return radius - p.norm(); }, radius + 3, spacing);
}

// An ellipsoid (semi-axes 30, 20, 15 mm) with a knob (radius 8 mm) on one side: no symmetry,
// so a rigid registration has one answer.
inline TriangleMesh knobbly_ellipsoid(double spacing = 1.0) {
  return implicit_surface(
      [](const Eigen::Vector3d& p) {
        const double ellipsoid = 15.0 * (1.0 - p.cwiseQuotient(Eigen::Vector3d(30, 20, 15)).norm());
        const double knob = 8.0 - (p - Eigen::Vector3d(20, 10, 8)).norm();
        return std::max(ellipsoid, knob);
      },
      34, spacing);
}

}  // namespace maxillo::validation::test
