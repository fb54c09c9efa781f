#include "imaging/distance_morphology.h"

#include <algorithm>
#include <limits>

namespace maxillo {
namespace {

constexpr float kFar = 1e20f;  // "no feature on this line": larger than any squared distance

// One line of the transform: f holds squared distances so far (0 at features, kFar elsewhere),
// spacing is the step along the line; on return f holds min_q f(q) + (spacing (p - q))^2. The
// lower envelope of the parabolas rooted at each q, as in Felzenszwalb & Huttenlocher (2012);
// kFar is an ordinary large value there, so lines without features stay about kFar.
void lower_envelope(std::vector<float>& f, double spacing, std::vector<int>& v, std::vector<double>& z,
                    std::vector<float>& out) {
  const int n = int(f.size());
  const double s2 = spacing * spacing;
  auto crossing = [&](int q, int p) {  // where the parabolas of q and p meet
    return ((double(f[size_t(q)]) + s2 * q * q) - (double(f[size_t(p)]) + s2 * p * p)) / (2 * s2 * (q - p));
  };
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  for (int q = 1; q < n; ++q) {
    double s = crossing(q, v[size_t(k)]);
    while (s <= z[size_t(k)]) {
      --k;
      s = crossing(q, v[size_t(k)]);
    }
    ++k;
    v[size_t(k)] = q;
    z[size_t(k)] = s;
    z[size_t(k) + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[size_t(k) + 1] < q) ++k;
    const int p = v[size_t(k)];
    out[size_t(q)] = float(double(f[size_t(p)]) + s2 * double(q - p) * double(q - p));
  }
  std::copy(out.begin(), out.end(), f.begin());
}

// Runs lower_envelope along `axis` for every line of the grid.
void transform_axis(std::vector<float>& d, const MaskGrid& g, int axis) {
  const size_t n = g.size[size_t(axis)];
  const size_t stride = axis == 0 ? 1 : axis == 1 ? g.size[0] : g.size[0] * g.size[1];
  std::vector<float> line(n), out(n);
  std::vector<int> v(n);
  std::vector<double> z(n + 1);
  const size_t lines = g.voxel_count() / n;
  for (size_t l = 0; l < lines; ++l) {
    // The first voxel of line l: skip the axis' own index.
    size_t first = 0;
    if (axis == 0)
      first = l * n;
    else if (axis == 1)
      first = (l % g.size[0]) + (l / g.size[0]) * g.size[0] * g.size[1];
    else
      first = l;
    for (size_t q = 0; q < n; ++q) line[q] = d[first + q * stride];
    lower_envelope(line, g.spacing[size_t(axis)], v, z, out);
    for (size_t q = 0; q < n; ++q) d[first + q * stride] = line[q];
  }
}

Mask complement(const Mask& mask) {
  Mask out(mask.size());
  for (size_t n = 0; n < mask.size(); ++n) out[n] = !mask[n];
  return out;
}

}  // namespace

std::vector<float> squared_distance_to(const Mask& to, const MaskGrid& grid) {
  std::vector<float> d(to.size());
  for (size_t n = 0; n < to.size(); ++n) d[n] = to[n] ? 0.0f : kFar;
  for (int axis = 0; axis < 3; ++axis) transform_axis(d, grid, axis);
  return d;
}

Mask dilated(const Mask& mask, const MaskGrid& grid, double radius_mm) {
  const auto d = squared_distance_to(mask, grid);
  const float r2 = float(radius_mm * radius_mm);
  Mask out(mask.size());
  for (size_t n = 0; n < d.size(); ++n) out[n] = d[n] <= r2;
  return out;
}

Mask eroded(const Mask& mask, const MaskGrid& grid, double radius_mm) {
  const auto d = squared_distance_to(complement(mask), grid);  // distance to the background
  const float r2 = float(radius_mm * radius_mm);
  Mask out(mask.size());
  for (size_t n = 0; n < d.size(); ++n) out[n] = d[n] > r2;
  return out;
}

Mask opened(const Mask& mask, const MaskGrid& grid, double radius_mm) {
  return dilated(eroded(mask, grid, radius_mm), grid, radius_mm);
}

Mask coarsened(const Mask& mask, const MaskGrid& grid, const std::array<size_t, 3>& factor, MaskGrid& coarse) {
  for (int a = 0; a < 3; ++a) {
    coarse.size[size_t(a)] = (grid.size[size_t(a)] + factor[size_t(a)] - 1) / factor[size_t(a)];
    coarse.spacing[size_t(a)] = grid.spacing[size_t(a)] * double(factor[size_t(a)]);
  }
  std::vector<uint32_t> set(coarse.voxel_count(), 0), total(coarse.voxel_count(), 0);
  for (size_t k = 0; k < grid.size[2]; ++k)
    for (size_t j = 0; j < grid.size[1]; ++j) {
      const size_t row = grid.index(0, j, k);
      const size_t coarse_row = coarse.index(0, j / factor[1], k / factor[2]);
      for (size_t i = 0; i < grid.size[0]; ++i) {
        set[coarse_row + i / factor[0]] += mask[row + i];
        ++total[coarse_row + i / factor[0]];
      }
    }
  Mask out(coarse.voxel_count());
  for (size_t n = 0; n < out.size(); ++n) out[n] = 2 * set[n] >= total[n] && set[n] > 0;
  return out;
}

Mask refined(const Mask& coarse_mask, const MaskGrid& coarse, const std::array<size_t, 3>& factor,
             const MaskGrid& fine) {
  Mask out(fine.voxel_count());
  for (size_t k = 0; k < fine.size[2]; ++k)
    for (size_t j = 0; j < fine.size[1]; ++j) {
      const size_t row = fine.index(0, j, k);
      const size_t coarse_row = coarse.index(0, j / factor[1], k / factor[2]);
      for (size_t i = 0; i < fine.size[0]; ++i) out[row + i] = coarse_mask[coarse_row + i / factor[0]];
    }
  return out;
}

}  // namespace maxillo
