#include "softtissue/face_region.h"

#include <algorithm>

namespace maxillo::softtissue {

LabelVolume face_region(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels,
                        const std::vector<RegionPlane>& planes) {
  const auto& g = tissues.geometry;
  LabelVolume region;
  region.geometry = g;
  region.labels.assign(tissues.labels.size(), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const auto v = size_t(g.index(i, j, k));
        if (std::find(soft_labels.begin(), soft_labels.end(), tissues.labels[v]) == soft_labels.end()) continue;
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        const bool kept =
            std::all_of(planes.begin(), planes.end(), [&](const RegionPlane& c) { return c.side(p) > 0; });
        region.labels[v] = kept ? 1 : 0;
      }
  return region;
}

}  // namespace maxillo::softtissue
