// Tissue segmentation (method in segmentation.h). Voxel-wise steps run here on plain buffers;
// connected components, ball morphology and hole filling are ITK's (itk_filters.cpp).
#include "imaging/segmentation.h"

#include <cmath>

#include "imaging/itk_filters.h"

namespace maxillo {
namespace {

using itk_filters::Grid;
using itk_filters::Mask;

Grid grid_of(const VolumeGeometry& g) {
  Grid grid;
  for (int a = 0; a < 3; ++a) {
    grid.size[a] = size_t(g.size[a]);
    grid.spacing[a] = g.spacing[a];
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

// Steps 1-3 of segmentation.h: the body without head rest or table, cavities not yet filled.
Mask body_without_support(const Mask& tissue, const Grid& grid, double gap_mm) {
  if (gap_mm <= 0) return itk_filters::largest_component(tissue, grid);
  Mask core = itk_filters::largest_component(itk_filters::opened(tissue, grid, gap_mm), grid);
  Mask body = itk_filters::dilated(core, grid, gap_mm);
  intersect(body, tissue);
  return itk_filters::largest_component(body, grid);
}

}  // namespace

LabelVolume segment_tissues(const Volume& volume, const SegmentationOptions& options) {
  const Grid grid = grid_of(volume.geometry);
  const Mask tissue = threshold(volume, options.skin_hu);
  const Mask body = body_without_support(tissue, grid, options.headrest_gap_mm);
  const Mask filled = itk_filters::holes_filled(body, grid);

  Mask bone = threshold(volume, options.bone_hu);
  intersect(bone, filled);
  const double voxel_mm3 = volume.geometry.spacing.prod();
  bone = itk_filters::components_of_at_least(bone, grid, int64_t(std::ceil(options.min_bone_island_mm3 / voxel_mm3)));

  LabelVolume labels{volume.geometry, std::vector<uint8_t>(volume.hu.size(), kBackground)};
  for (size_t n = 0; n < labels.labels.size(); ++n) {
    if (!filled[n]) continue;
    if (bone[n]) labels.labels[n] = volume.hu[n] >= options.teeth_hu ? kTeeth : kBone;
    else labels.labels[n] = body[n] ? kSoftTissue : kEnclosedAir;
  }
  return labels;
}

}  // namespace maxillo
