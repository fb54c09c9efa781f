#include "validation/distance_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "geometry/signed_distance.h"

namespace maxillo::validation {

double percentile(std::vector<double> values, double percent) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const double rank = std::clamp(percent, 0.0, 100.0) / 100.0 * double(values.size() - 1);
  const auto below = size_t(std::floor(rank));
  const auto above = std::min(below + 1, values.size() - 1);
  return values[below] + (rank - double(below)) * (values[above] - values[below]);
}

DistanceStatistics distance_statistics(std::span<const double> signed_mm, double tolerance_mm) {
  DistanceStatistics s;
  s.count = int(signed_mm.size());
  if (signed_mm.empty()) return s;
  const double n = double(signed_mm.size());
  double absolute = 0, sum = 0, within = 0;
  for (double d : signed_mm) {
    absolute += std::abs(d);
    sum += d;
    within += std::abs(d) <= tolerance_mm;
    s.max_absolute = std::max(s.max_absolute, std::abs(d));
  }
  s.mean_absolute = absolute / n;
  s.mean_signed = sum / n;
  double squares = 0;
  for (double d : signed_mm) squares += (d - s.mean_signed) * (d - s.mean_signed);
  s.standard_deviation = signed_mm.size() > 1 ? std::sqrt(squares / (n - 1)) : 0.0;
  const std::vector<double> values(signed_mm.begin(), signed_mm.end());
  s.p5 = percentile(values, 5);
  s.p25 = percentile(values, 25);
  s.p50 = percentile(values, 50);
  s.p75 = percentile(values, 75);
  s.p90 = percentile(values, 90);
  s.p95 = percentile(values, 95);
  s.within_tolerance_percent = 100.0 * within / n;
  return s;
}

std::vector<double> signed_surface_distances(const TriangleMesh& predicted, const TriangleMesh& actual,
                                             const std::vector<bool>& include, double max_distance_mm) {
  return defined_values(signed_distance_map(predicted, actual, include, max_distance_mm));
}

std::vector<double> signed_distance_map(const TriangleMesh& predicted, const TriangleMesh& actual,
                                        const std::vector<bool>& include, double max_distance_mm) {
  const DistanceField field(actual);
  std::vector<double> map(size_t(predicted.vertex_count()), std::numeric_limits<double>::quiet_NaN());
  for (Eigen::Index v = 0; v < predicted.vertex_count(); ++v) {
    if (!include.empty() && !include[size_t(v)]) continue;
    const auto d = field.signed_distance(predicted.vertices.row(v).transpose(), max_distance_mm);
    if (d.found) map[size_t(v)] = d.distance;
  }
  return map;
}

std::vector<double> defined_values(const std::vector<double>& map, const std::vector<bool>& include) {
  std::vector<double> values;
  for (size_t i = 0; i < map.size(); ++i)
    if (!std::isnan(map[i]) && (include.empty() || include[i])) values.push_back(map[i]);
  return values;
}

}  // namespace maxillo::validation
