#pragma once
// Voxelisation of the phantom's parts and conversion to Hounsfield units.
#include <vector>

#include "core/volume.h"
#include "sample/phantom_parts.h"

namespace maxillo::sample {

struct PaintedGrid {
  VolumeGeometry geometry;
  std::vector<uint8_t> tissue;     // Tissue per voxel
  std::vector<Material> material;  // Material per voxel
};

// Paints the parts in order at voxel centres (later parts win where their mask allows).
// Work is split over z slabs on the available cores; the result does not depend on it.
PaintedGrid paint_parts(const PartList& parts, const VolumeGeometry& geometry);

// HU from materials. Bone within 2 mm (city-block) of non-bone is cortical (1500 HU), deeper
// bone cancellous (450 HU); enamel 2800, dentine 1900, soft tissue 40, fat -90, brain 35,
// vitreous 10, air -1000, head rest 60, table 150. Then the optional [1 2 1]/4 blur along each
// axis and Gaussian noise (Box-Muller, mt19937_64 seeded per z slice from the spec's seed),
// clamped to [-1024, 3071]. The cone-beam flavour (phantom_cone_beam.h) adds cupping and metal
// streaks before the noise and maps the clamped HU to its grey values after.
Volume compute_ct(const PaintedGrid& grid, const PhantomSpec& spec);

}  // namespace maxillo::sample
