#pragma once
// Binary morphology with balls of a radius in millimetres, by exact Euclidean distance
// transforms instead of sweeping a structuring element: an erosion by a ball of radius r keeps
// the voxels farther than r from the background, a dilation adds those within r of the mask.
// The cost does not grow with the radius (a 3 mm ball on 0.5 mm voxels is 7^3 = 343 offsets per
// voxel for a structuring element; here it is three passes whatever r).
//
// Large balls do not need fine voxels: coarsened() averages blocks into a coarser mask on which
// the morphology runs, refined() brings the result back to the fine grid.
#include "imaging/mask_grid.h"

namespace maxillo {

// Squared Euclidean distance (mm^2) from every voxel centre to the nearest voxel centre with
// `to` set; a huge value where `to` is empty (Felzenszwalb & Huttenlocher's lower envelope of
// parabolas, one pass per axis, with the grid's spacing).
std::vector<float> squared_distance_to(const Mask& to, const MaskGrid& grid);

// The voxels farther than radius_mm from the background (an erosion by a ball).
Mask eroded(const Mask& mask, const MaskGrid& grid, double radius_mm);
// Erosion then dilation by a ball of radius_mm: removes what is thinner than about 2 radius_mm.
Mask opened(const Mask& mask, const MaskGrid& grid, double radius_mm);
// Every voxel within radius_mm of the mask.
Mask dilated(const Mask& mask, const MaskGrid& grid, double radius_mm);

// Blocks of factor[a] voxels along each axis become one voxel, set where at least half of the
// block is set; the grid of the result is written to `coarse`.
Mask coarsened(const Mask& mask, const MaskGrid& grid, const std::array<size_t, 3>& factor, MaskGrid& coarse);
// Each coarse voxel back onto the fine voxels of its block (`fine` is the grid coarsened from).
Mask refined(const Mask& coarse_mask, const MaskGrid& coarse, const std::array<size_t, 3>& factor,
             const MaskGrid& fine);

}  // namespace maxillo
