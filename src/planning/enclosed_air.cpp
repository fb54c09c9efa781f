#include "planning/enclosed_air.h"

#include <cassert>

#include "planning/voxel_components.h"

namespace maxillo::planning {

LabelVolume with_enclosed_air(const LabelVolume& tissues, const Volume& ct, double air_below_hu, uint8_t enclosed) {
  assert(tissues.labels.size() == ct.hu.size() && "tissues and ct must share the grid");
  const VolumeGeometry& g = ct.geometry;
  std::vector<uint8_t> air(ct.hu.size());
  for (size_t n = 0; n < air.size(); ++n) air[n] = ct.hu[n] < air_below_hu;
  const VoxelComponents components = voxel_components(air, g.size);
  // Components with a voxel on a face of the volume are outside air.
  std::vector<bool> outside(static_cast<size_t>(components.count) + 1, false);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const bool on_face =
            i == 0 || j == 0 || k == 0 || i == g.size.x() - 1 || j == g.size.y() - 1 || k == g.size.z() - 1;
        if (on_face) outside[components.id[g.index(i, j, k)]] = true;
      }
  LabelVolume result = tissues;
  for (size_t n = 0; n < air.size(); ++n) {
    const int32_t id = components.id[n];
    if (id > 0 && !outside[id]) result.labels[n] = enclosed;
  }
  return result;
}

}  // namespace maxillo::planning
