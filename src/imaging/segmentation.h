#pragma once
// Threshold segmentation of a head CT into tissue labels on the volume's own grid.
// The morphology runs on exact distance maps and run-length components (distance_morphology.h,
// mask_components.h), without ITK; this header speaks maxillo types only.
//
// Body (everything inside the skin):
//   1. HU >= skin_hu (air ~ -1000, fat ~ -100, skin/soft tissue ~ 0..+80; -400 sits midway);
//   2. binary opening with a ball of headrest_gap_mm radius: detaches a head rest, table or
//      cushion that touches the skin over a thin contact (thinner than ~2 x radius);
//   3. the largest connected component, dilated back by the same ball and intersected with
//      step 1 (restores ears and nose rims the opening thinned), largest component again;
//   4. the pieces the opening cut off put back where they are soft tissue: at most
//      max_restored_piece_mm3 and of soft tissue's mean grey value (-150 to +150 HU). A nose
//      whose walls, with the nostrils behind them, are thinner than the ball is cut off whole (the
//      cadaver head's was, and its face model had no nose); a head rest or a table is a larger
//      piece, a pad, a cushion or metal streaks in the air are not soft tissue's grey;
//   5. enclosed cavities filled (3D hole filling: sinuses or airway pockets with no opening
//      to the outside at this resolution).
// Bone: HU >= bone_hu inside the body; with bone_edge_at_half_maximum its boundary voxels kept
// only where they reach half-way between the bone and what lies beside it (half_maximum_edge.h:
// the threshold alone lays a voxel of partial volume over every bone); islands smaller than
// min_bone_island_mm3 dropped.
// Teeth: bone voxels with HU >= teeth_hu (enamel, dense dentine, fillings).
// Enclosed air: cavities filled in step 5 (maxillary/frontal sinus air where it is closed off).
#include <cstdint>

#include "core/volume.h"

namespace maxillo {

enum TissueLabel : uint8_t {
  kBackground = 0,
  kSoftTissue = 1,   // inside the body, neither bone nor enclosed air
  kEnclosedAir = 2,  // air cavities inside the body with no path to the outside
  kBone = 3,
  kTeeth = 4,
};

struct SegmentationOptions {
  double skin_hu = -400;
  double bone_hu = 300;
  double teeth_hu = 1500;
  double headrest_gap_mm = 3;             // opening radius (step 2 above); 0 disables the opening
  double max_restored_piece_mm3 = 50000;  // step 4: larger pieces cut off the body stay outside it
  double min_bone_island_mm3 = 200;       // smaller bone pieces are noise, metal streaks or debris
  // true: the bone's boundary by the half-maximum rule (bone Dice 0.97-0.98 on the phantom, 0.90
  // by the threshold alone). Not the default yet: the face models are built and checked on the
  // threshold's bone, and the non-linear FEM does not converge on the phantom's trimmed one.
  bool bone_edge_at_half_maximum = false;

  bool operator==(const SegmentationOptions&) const = default;
};

// One label per voxel (TissueLabel values), same geometry as `volume`.
LabelVolume segment_tissues(const Volume& volume, const SegmentationOptions& options = {});

// 1 where mask.labels is in [first, last], 0 elsewhere (e.g. kBone..kTeeth for all bone).
LabelVolume select_labels(const LabelVolume& labels, uint8_t first, uint8_t last);

// A copy of `volume` whose iso_hu level set is the boundary of `mask`, keeping the CT's
// sub-voxel interpolation where it agrees with the mask: voxels in the mask are raised to at
// least iso_hu + 1, voxels outside lowered to at most iso_hu - 1. Feed it to extract_surface
// with the same iso_hu to get a smooth surface of exactly the segmented region.
Volume restrict_to_mask(const Volume& volume, const LabelVolume& mask, double iso_hu);

}  // namespace maxillo
