// Tissue segmentation (method in segmentation.h), in plain C++ on byte masks: connected
// components on runs (mask_components.h), the head-rest opening by distance transforms on a
// grid of about 1 mm (distance_morphology.h).
#include "imaging/segmentation.h"

#include <cmath>

#include "imaging/distance_morphology.h"
#include "imaging/half_maximum_edge.h"
#include "imaging/label_masks.h"
#include "imaging/mask_components.h"

namespace maxillo {
namespace {

// The opening that detaches a head rest works with a ball of a few millimetres: voxels of a
// third of its radius resolve it. Finer CTs are coarsened by whole voxels down to that.
constexpr double kOpeningVoxelsPerRadius = 3;

// The mean grey value of a piece put back (step 4): fat (-100) to cartilage (+100), with the
// partial volume of a thin wall.
constexpr double kThinSoftTissueHu[2] = {-150, 150};

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

// Step 4 of segmentation.h: what the opening cut off the body (`whole` without `body`) falls
// into pieces; each touches the body, since `whole` is connected. A nose tip, an ear's rim or a
// lip thinner than the ball is cut off whole as a small piece of soft tissue's grey values, and is
// body again. A head rest or a table is a large piece; a pad or cushion and metal streaks in the
// air are not soft tissue's grey (on the cadaver head: the pad's pieces -319 HU on average, the
// streaks in front of the teeth +258 and +365, the nose +7, the ears -60 and -65).
void restore_thin_soft_tissue(Mask& body, const Mask& whole, const MaskGrid& grid, const Volume& volume,
                              double max_piece_mm3) {
  Mask cut_off(whole.size(), 0);
  for (size_t n = 0; n < cut_off.size(); ++n) cut_off[n] = whole[n] && !body[n];
  const ComponentLabels pieces = label_components(cut_off, grid);
  std::vector<double> hu_sum(pieces.voxels.size(), 0.0);
  for (size_t n = 0; n < cut_off.size(); ++n) hu_sum[size_t(pieces.label[n])] += volume.hu[n];
  const double voxel_mm3 = grid.spacing[0] * grid.spacing[1] * grid.spacing[2];
  std::vector<uint8_t> restore(pieces.voxels.size(), 0);
  for (int32_t c = 1; c <= pieces.count(); ++c) {
    const double mean_hu = hu_sum[size_t(c)] / double(pieces.voxels[size_t(c)]);
    restore[size_t(c)] = double(pieces.voxels[size_t(c)]) * voxel_mm3 <= max_piece_mm3 &&
                         mean_hu >= kThinSoftTissueHu[0] && mean_hu <= kThinSoftTissueHu[1];
  }
  for (size_t n = 0; n < body.size(); ++n)
    if (restore[size_t(pieces.label[n])]) body[n] = 1;
}

// Steps 1-4 of segmentation.h: the body without head rest or table, cavities not yet filled.
// The opening and the dilation back run on the coarse grid; only where the dilated core cuts
// the tissue (at a head rest's contact) does its coarser boundary show, a millimetre at most.
Mask body_without_support(const Mask& tissue, const MaskGrid& grid, const Volume& volume, double gap_mm,
                          double max_piece_mm3) {
  if (gap_mm <= 0) return largest_component(tissue, grid);
  const auto factor = opening_factors(grid, gap_mm);
  MaskGrid coarse;
  const Mask coarse_tissue = coarsened(tissue, grid, factor, coarse);
  const MaskGrid ball = voxel_ball_grid(coarse, gap_mm);
  const Mask core = largest_component(opened(coarse_tissue, ball, 1.0), coarse);
  Mask body = refined(dilated(core, ball, 1.0), coarse, factor, grid);
  intersect(body, tissue);
  body = largest_component(body, grid);
  if (max_piece_mm3 > 0) restore_thin_soft_tissue(body, largest_component(tissue, grid), grid, volume, max_piece_mm3);
  return body;
}

}  // namespace

LabelVolume segment_tissues(const Volume& volume, const SegmentationOptions& options) {
  const MaskGrid grid = grid_of(volume.geometry);
  const Mask body = body_without_support(threshold(volume, options.skin_hu), grid, volume, options.headrest_gap_mm,
                                         options.max_restored_piece_mm3);
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
