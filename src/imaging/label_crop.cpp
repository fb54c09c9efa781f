#include "imaging/label_crop.h"

#include <algorithm>

#include "core/error.h"

namespace maxillo {
namespace {

VolumeGeometry cropped_geometry(const VolumeGeometry& g, const VoxelBox& box) {
  VolumeGeometry crop = g;
  crop.size = box.hi - box.lo + Eigen::Vector3i::Ones();
  crop.origin = g.world(box.lo.cast<double>());
  return crop;
}

template <typename Value>
std::vector<Value> cropped_values(const std::vector<Value>& values, const VolumeGeometry& g, const VoxelBox& box) {
  const VolumeGeometry crop = cropped_geometry(g, box);
  std::vector<Value> out(size_t(crop.voxel_count()));
  for (int k = 0; k < crop.size.z(); ++k)
    for (int j = 0; j < crop.size.y(); ++j)
      for (int i = 0; i < crop.size.x(); ++i)
        out[size_t(crop.index(i, j, k))] = values[size_t(g.index(box.lo.x() + i, box.lo.y() + j, box.lo.z() + k))];
  return out;
}

}  // namespace

VoxelBox box_of_labels(const LabelVolume& volume, std::initializer_list<uint8_t> labels, int margin,
                       const std::string& subject) {
  const VolumeGeometry& g = volume.geometry;
  VoxelBox box{g.size, Eigen::Vector3i::Constant(-1)};
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const uint8_t l = volume.labels[size_t(g.index(i, j, k))];
        if (std::find(labels.begin(), labels.end(), l) == labels.end()) continue;
        box.lo = box.lo.cwiseMin(Eigen::Vector3i(i, j, k));
        box.hi = box.hi.cwiseMax(Eigen::Vector3i(i, j, k));
      }
  if (box.hi.x() < 0) throw Error(ErrorCode::kProcessing, subject, "no voxel carries the labels looked for");
  box.lo = (box.lo - Eigen::Vector3i::Constant(margin)).cwiseMax(Eigen::Vector3i::Zero());
  box.hi = (box.hi + Eigen::Vector3i::Constant(margin)).cwiseMin(g.size - Eigen::Vector3i::Ones());
  return box;
}

LabelVolume cropped(const LabelVolume& volume, const VoxelBox& box) {
  return LabelVolume{cropped_geometry(volume.geometry, box), cropped_values(volume.labels, volume.geometry, box)};
}

Volume cropped(const Volume& volume, const VoxelBox& box) {
  return Volume{cropped_geometry(volume.geometry, box), cropped_values(volume.hu, volume.geometry, box)};
}

}  // namespace maxillo
