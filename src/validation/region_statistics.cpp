#include "validation/region_statistics.h"

namespace maxillo::validation {

std::vector<RegionValues> statistics_by_region(const std::vector<double>& per_vertex,
                                               const std::vector<FaceRegion>& regions, double tolerance_mm) {
  auto of = [&](FaceRegion region) {
    return distance_statistics(defined_values(per_vertex, region_mask(regions, region)), tolerance_mm);
  };
  std::vector<RegionValues> rows{{"face", of(FaceRegion::kOutside)}};
  for (auto region : kFaceSubregions) rows.push_back({std::string(region_name(region)), of(region)});
  return rows;
}

}  // namespace maxillo::validation
