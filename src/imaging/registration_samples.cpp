// Metric samples chosen by canonical voxel index (see registration_samples.h).
#include "imaging/registration_samples.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace maxillo {
namespace {

// How storage axes map onto canonical (LPS-aligned) axes.
struct CanonicalAxes {
  std::array<int, 3> storage_axis{0, 1, 2};  // for LPS axis p, the storage axis along it
  std::array<bool, 3> reversed{};            // the storage axis runs along -p
};

// Each storage axis goes to the LPS axis its direction is closest to. A direction so oblique
// that two storage axes claim the same LPS axis keeps the storage order (no such CT reaches
// here: tilted series are refused on assembly).
CanonicalAxes canonical_axes(const VolumeGeometry& g) {
  CanonicalAxes axes;
  std::array<bool, 3> taken{};
  for (int a = 0; a < 3; ++a) {
    int p = 0;
    g.direction.col(a).cwiseAbs().maxCoeff(&p);
    if (taken[size_t(p)]) return CanonicalAxes{};
    taken[size_t(p)] = true;
    axes.storage_axis[size_t(p)] = a;
    axes.reversed[size_t(p)] = g.direction(p, a) < 0;
  }
  return axes;
}

// SplitMix64's finaliser: a well-mixed 64-bit hash of a 64-bit key.
uint64_t mixed(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A uniform number in (0, 1) from a key.
double uniform(uint64_t key) { return (double(mixed(key) >> 11) + 0.5) * 0x1.0p-53; }

// A standard normal deviate from a key (Box-Muller).
double normal(uint64_t key) {
  const double radius = std::sqrt(-2 * std::log(uniform(2 * key)));
  return radius * std::cos(2 * M_PI * uniform(2 * key + 1));
}

}  // namespace

std::vector<std::array<double, 3>> metric_samples(const VolumeGeometry& fixed, const std::vector<uint8_t>& mask,
                                                  const MetricSampling& sampling) {
  const CanonicalAxes axes = canonical_axes(fixed);
  const uint64_t stride = uint64_t(std::max(1.0, std::ceil(sampling.level_factor / sampling.fraction)));
  const uint64_t stream = mixed(sampling.seed) ^ mixed(uint64_t(sampling.level_factor) << 32);
  const uint64_t phase = mixed(stream) % stride;
  std::array<double, 3> sigma{};  // jitter along each LPS axis, mm
  std::array<int64_t, 3> extent{};
  for (size_t p = 0; p < 3; ++p) {
    const int a = axes.storage_axis[p];
    sigma[p] = sampling.level_factor * fixed.spacing[a] / 3;
    extent[p] = fixed.size[a];
  }

  std::vector<std::pair<uint64_t, std::array<double, 3>>> chosen;
  for (int k = 0; k < fixed.size.z(); ++k)
    for (int j = 0; j < fixed.size.y(); ++j)
      for (int i = 0; i < fixed.size.x(); ++i) {
        if (!mask[size_t(fixed.index(i, j, k))]) continue;
        const std::array<int64_t, 3> ijk{i, j, k};
        std::array<int64_t, 3> c{};
        for (size_t p = 0; p < 3; ++p) {
          const int64_t n = ijk[size_t(axes.storage_axis[p])];
          c[p] = axes.reversed[p] ? extent[p] - 1 - n : n;
        }
        const uint64_t canonical = uint64_t(c[0] + extent[0] * (c[1] + extent[1] * c[2]));
        const uint64_t key = mixed(canonical ^ stream);
        const bool taken = sampling.pattern == SamplePattern::kJitteredGrid ? (canonical + phase) % stride == 0
                                                                            : uniform(key) * double(stride) < 1;
        if (!taken) continue;
        Eigen::Vector3d point = fixed.world(Eigen::Vector3d(i, j, k));
        for (int p = 0; p < 3; ++p) point[p] += sigma[size_t(p)] * normal(4 * key + uint64_t(p) + 1);
        chosen.push_back({canonical, {point.x(), point.y(), point.z()}});
      }
  std::sort(chosen.begin(), chosen.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::array<double, 3>> points;
  points.reserve(chosen.size());
  for (const auto& [canonical, point] : chosen) points.push_back(point);
  return points;
}

}  // namespace maxillo
