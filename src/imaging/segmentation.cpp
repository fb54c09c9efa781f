// Tissue segmentation (method in segmentation.h), in plain C++ on byte masks: connected
// components on runs (mask_components.h), the head-rest opening by distance transforms on a
// grid of about 1 mm (distance_morphology.h).
#include "imaging/segmentation.h"

#include <cmath>

#include "imaging/distance_morphology.h"
#include "imaging/half_maximum_edge.h"
#include "imaging/mask_components.h"

namespace maxillo {
namespace {

// The opening that detaches a head rest works with a ball of a few millimetres: voxels of a
// third of its radius resolve it. Finer CTs are coarsened by whole voxels down to that.
constexpr double kOpeningVoxelsPerRadius = 3;

MaskGrid grid_of(const VolumeGeometry& g) {
  MaskGrid grid;
  for (int a = 0; a < 3; ++a) {
    grid.size[size_t(a)] = size_t(g.size[a]);
    grid.spacing[size_t(a)] = g.spacing[a];
  }
  return grid;
}

Mask threshold(const Volume& volume, double lowest_hu) {
  Mask mask(volume.hu.size());
  for (size_t n = 0; n < mask.size(); ++n) mask[n] = volume.hu[n] >= lowest_hu ? 1 : 0;
  return mask;
}

void intersect(Mask& mask, const Mask& other) {
  for (size_t n = 0; n < mask.size(); ++n) mask[n] = mask[n] && other[n];
}

std::array<size_t, 3> opening_factors(const MaskGrid& grid, double gap_mm) {
  std::array<size_t, 3> factor{};
  for (size_t a = 0; a < 3; ++a)
    factor[a] = std::max<size_t>(1, size_t(std::floor(gap_mm / kOpeningVoxelsPerRadius / grid.spacing[a])));
  return factor;
}

// The ball of step 2 as a voxel ball: round(r / spacing) voxels along each axis (at least one),
// holding the voxel centres within that plus half a voxel (as ITK's BinaryBallStructuringElement,
// which this replaced; the segmentation, and the faces predicted from it, stay as they were).
// Distances measured on a grid whose spacing is 1 / (that radius) along each axis make this
// ellipsoid the unit ball.
MaskGrid voxel_ball_grid(const MaskGrid& grid, double radius_mm) {
  MaskGrid scaled = grid;
  for (size_t a = 0; a < 3; ++a)
    scaled.spacing[a] = 1.0 / (std::max(1.0, std::round(radius_mm / grid.spacing[a])) + 0.5);
  return scaled;
}

// Steps 1-3 of segmentation.h: the body without head rest or table, cavities not yet filled.
// The opening and the dilation back run on the coarse grid; only where the dilated core cuts
// the tissue (at a head rest's contact) does its coarser boundary show, a millimetre at most.
Mask body_without_support(const Mask& tissue, const MaskGrid& grid, double gap_mm) {
  if (gap_mm <= 0) return largest_component(tissue, grid);
  const auto factor = opening_factors(grid, gap_mm);
  MaskGrid coarse;
  const Mask coarse_tissue = coarsened(tissue, grid, factor, coarse);
  const MaskGrid ball = voxel_ball_grid(coarse, gap_mm);
  const Mask core = largest_component(opened(coarse_tissue, ball, 1.0), coarse);
  Mask body = refined(dilated(core, ball, 1.0), coarse, factor, grid);
  intersect(body, tissue);
  return largest_component(body, grid);
}

}  // namespace

LabelVolume segment_tissues(const Volume& volume, const SegmentationOptions& options) {
  const MaskGrid grid = grid_of(volume.geometry);
  const Mask body = body_without_support(threshold(volume, options.skin_hu), grid, options.headrest_gap_mm);
  const Mask filled = holes_filled(body, grid);

  Mask bone = threshold(volume, options.bone_hu);
  intersect(bone, filled);
  if (options.bone_edge_at_half_maximum) trim_to_half_maximum(bone, grid, volume.hu);
  const double voxel_mm3 = volume.geometry.spacing.prod();
  bone = components_of_at_least(bone, grid, int64_t(std::ceil(options.min_bone_island_mm3 / voxel_mm3)));

  LabelVolume labels{volume.geometry, std::vector<uint8_t>(volume.hu.size(), kBackground)};
  for (size_t n = 0; n < labels.labels.size(); ++n) {
    if (!filled[n]) continue;
    if (bone[n])
      labels.labels[n] = volume.hu[n] >= options.teeth_hu ? kTeeth : kBone;
    else
      labels.labels[n] = body[n] ? kSoftTissue : kEnclosedAir;
  }
  return labels;
}

}  // namespace maxillo
