#include "imaging/enclosed_tissue.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "imaging/distance_morphology.h"
#include "imaging/label_crop.h"
#include "imaging/label_masks.h"
#include "imaging/mask_components.h"

namespace maxillo {
namespace {

// The air the face's skin meets reaches it through openings wider than this radius's ball (the
// nostrils, the mouth); the sinuses drain through ostia of 2-5 mm.
constexpr double kOstiumRadiusMm = 2.5;

// Which cores come within reach of the outside air: open[c] for core c (index 0 unused).
std::vector<bool> open_cores(const ComponentLabels& cores, const Mask& air, const MaskGrid& grid, double reach_mm) {
  const auto to_air = squared_distance_to(air, grid);
  const float reach2 = float(reach_mm * reach_mm);
  std::vector<bool> open(cores.voxels.size(), false);
  for (size_t n = 0; n < to_air.size(); ++n)
    if (cores.label[n] > 0 && to_air[n] <= reach2) open[size_t(cores.label[n])] = true;
  return open;
}

// The air around the head and what opens wide onto it: the air joined to the box's border
// through openings wider than 2 neck_mm. A sinus's ostium is narrower, and the sinus's air, which
// lies against the brain behind a wall of bone too thin for the CT to resolve everywhere, is not
// taken for the air the face's skin meets.
Mask air_around(const Mask& air, const MaskGrid& grid, double neck_mm) {
  const auto wide = label_components(eroded(air, grid, neck_mm), grid);
  std::vector<bool> outside(wide.voxels.size(), false);
  for (size_t k = 0; k < grid.size[2]; ++k)
    for (size_t j = 0; j < grid.size[1]; ++j)
      for (size_t i = 0; i < grid.size[0]; ++i) {
        const bool border =
            i == 0 || j == 0 || k == 0 || i + 1 == grid.size[0] || j + 1 == grid.size[1] || k + 1 == grid.size[2];
        if (border) outside[size_t(wide.label[grid.index(i, j, k)])] = true;
      }
  Mask core(air.size(), 0);
  for (size_t n = 0; n < air.size(); ++n) core[n] = wide.label[n] > 0 && outside[size_t(wide.label[n])];
  Mask around = dilated(core, grid, neck_mm);
  for (size_t n = 0; n < air.size(); ++n) around[n] = around[n] && air[n];
  return around;
}

// The parts of `tissue` joined (6-connected, within it) to a voxel of `anchors`.
Mask held_by(const Mask& tissue, const Mask& anchors, const MaskGrid& grid) {
  const auto pieces = label_components(tissue, grid);
  std::vector<bool> held(pieces.voxels.size(), false);
  for (size_t n = 0; n < tissue.size(); ++n)
    if (anchors[n] && pieces.label[n] > 0) held[size_t(pieces.label[n])] = true;
  Mask out(tissue.size(), 0);
  for (size_t n = 0; n < tissue.size(); ++n) out[n] = pieces.label[n] > 0 && held[size_t(pieces.label[n])];
  return out;
}

int64_t count(const Mask& mask) { return std::count(mask.begin(), mask.end(), uint8_t(1)); }

void paste(LabelVolume& into, const Mask& part, const VoxelBox& box) {
  const VolumeGeometry& g = into.geometry;
  const Eigen::Vector3i size = box.hi - box.lo + Eigen::Vector3i::Ones();
  for (int k = 0; k < size.z(); ++k)
    for (int j = 0; j < size.y(); ++j)
      for (int i = 0; i < size.x(); ++i)
        into.labels[size_t(g.index(box.lo.x() + i, box.lo.y() + j, box.lo.z() + k))] =
            part[size_t(i + int64_t(size.x()) * (j + int64_t(size.y()) * k))];
}

}  // namespace

EnclosedTissue without_enclosed_tissue(const LabelVolume& tissue, const LabelVolume& labels, uint8_t outside_air,
                                       double neck_radius_mm) {
  if (tissue.geometry.size != labels.geometry.size)
    throw Error(ErrorCode::kBadValue, "enclosed tissue", "the tissue and its labels are on different grids");
  const double voxel_mm = tissue.geometry.spacing.norm();  // a voxel's diagonal
  const int margin = int(std::ceil((neck_radius_mm + 2 * voxel_mm) / tissue.geometry.spacing.minCoeff()));
  const VoxelBox box = box_of_labels(tissue, {1}, margin, "enclosed tissue");
  const LabelVolume local = cropped(tissue, box);
  const MaskGrid grid = grid_of(local.geometry);
  const Mask soft = mask_of_labels(local, {1});
  const Mask air = air_around(mask_of_labels(cropped(labels, box), {outside_air}), grid, kOstiumRadiusMm);

  const auto cores = label_components(eroded(soft, grid, neck_radius_mm), grid);
  const auto open = open_cores(cores, air, grid, neck_radius_mm + voxel_mm);
  Mask open_core(soft.size(), 0), enclosed_core(soft.size(), 0);
  for (size_t n = 0; n < soft.size(); ++n)
    if (cores.label[n] > 0) (open[size_t(cores.label[n])] ? open_core : enclosed_core)[n] = 1;
  const Mask enclosed = dilated(enclosed_core, grid, neck_radius_mm);

  Mask rest = soft;
  for (size_t n = 0; n < rest.size(); ++n) rest[n] = soft[n] && !enclosed[n];
  const Mask kept = held_by(rest, open_core, grid);

  EnclosedTissue result;
  result.kept.geometry = tissue.geometry;
  result.kept.labels.assign(tissue.labels.size(), 0);
  paste(result.kept, kept, box);
  result.enclosed_voxels = count(soft) - count(rest);
  result.loose_voxels = count(rest) - count(kept);
  return result;
}

}  // namespace maxillo
