#pragma once
// How far a predicted surface lies from the real one (thesis ch. 6 Tables 2-3, ch. 8): the
// signed closest-point distance of every predicted vertex to the actual surface (negative: the
// prediction lies behind the real surface, inside it), and the statistics the source reports.
#include <span>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::validation {

struct DistanceStatistics {
  int count = 0;
  double mean_absolute = 0, mean_signed = 0, standard_deviation = 0;  // SD of the signed values
  double p5 = 0, p25 = 0, p50 = 0, p75 = 0, p90 = 0, p95 = 0;         // of the signed values
  double max_absolute = 0;
  double within_tolerance_percent = 0;  // |d| <= tolerance (the source's +-2 mm)
};

// Percentiles by linear interpolation between order statistics (the "type 7" definition of R
// and NumPy's default), so a percentile of a constant sample is that constant.
double percentile(std::vector<double> values, double percent);

// Statistics of signed distances (mm). An empty sample gives count 0 and zeros.
DistanceStatistics distance_statistics(std::span<const double> signed_mm, double tolerance_mm = 2.0);

// Signed distance of each vertex of `predicted` to `actual` (a closed, outward-oriented
// surface), for the vertices where `include` is true (all when empty). Vertices with no actual
// surface within max_distance_mm are left out. Returns one value per included vertex found.
std::vector<double> signed_surface_distances(const TriangleMesh& predicted, const TriangleMesh& actual,
                                             const std::vector<bool>& include = {}, double max_distance_mm = 20.0);

// The same as a map over every vertex of `predicted`: NaN where a vertex is not included or has
// no actual surface within reach (for colour maps and per-region statistics).
std::vector<double> signed_distance_map(const TriangleMesh& predicted, const TriangleMesh& actual,
                                        const std::vector<bool>& include = {}, double max_distance_mm = 20.0);
// The values of a map where it is defined (not NaN) and `include` holds (all when empty).
std::vector<double> defined_values(const std::vector<double>& map, const std::vector<bool>& include = {});

}  // namespace maxillo::validation
