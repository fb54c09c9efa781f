#pragma once
// Distance statistics for the whole face region and each of its subregions, from one value per
// skin vertex: the validation's tables and the synthetic case's known answer are made the same way.
#include <string>
#include <vector>

#include "validation/distance_statistics.h"
#include "validation/face_regions.h"

namespace maxillo::validation {

struct RegionValues {
  std::string region;  // "face" (every region) first, then kFaceSubregions' names
  DistanceStatistics statistics;
};

// `per_vertex`: NaN where undefined (left out); `regions`: one per vertex.
std::vector<RegionValues> statistics_by_region(const std::vector<double>& per_vertex,
                                               const std::vector<FaceRegion>& regions, double tolerance_mm = 2.0);

}  // namespace maxillo::validation
