#pragma once
// Where the registration metric looks: points of the fixed CT, chosen by the anatomy they sit on
// rather than by how the CT happens to be stored (internal to src/imaging; see
// rigid_registration.h).
//
// A voxel is named by its canonical index: its (i, j, k) re-ordered and reversed so that the
// canonical axes run along +x, +y, +z of LPS (each storage axis goes to the LPS axis it is
// closest to). Two copies of a CT that differ only in storage order (slices top-down or
// bottom-up, rows flipped) or in where they put the origin give every voxel the same canonical
// index, so they choose the same voxels, jitter them alike and list them in the same order; the
// metric then sums the same terms in the same order. ITK's own samplers count voxels in storage
// order, and a copy converted with slices the other way round registered 0.015 deg away.
//
// Pattern: every `stride`-th voxel in canonical order (a jittered regular grid, ITK's REGULAR),
// or each voxel with probability 1 / stride (RANDOM); only voxels of the mask are kept. The
// point is the voxel centre moved along each LPS axis by a normal deviate of a third of the
// level's voxel (as ITK jitters). Every choice derives from (canonical index, seed) by a hash,
// never from a generator's state, so the set does not depend on iteration order.
#include <array>
#include <cstdint>
#include <vector>

#include "core/volume.h"

namespace maxillo {

enum class SamplePattern { kJitteredGrid, kRandom };

struct MetricSampling {
  double fraction = 0.01;  // of the full-resolution voxels, before the mask
  int level_factor = 1;    // pyramid level: voxels level_factor times the CT's; stride level_factor / fraction
  SamplePattern pattern = SamplePattern::kJitteredGrid;
  uint32_t seed = 1;
};

// Sample points (LPS mm) in canonical order. `mask` has one byte per voxel of `fixed` (x fastest);
// non-zero = may be sampled.
std::vector<std::array<double, 3>> metric_samples(const VolumeGeometry& fixed, const std::vector<uint8_t>& mask,
                                                  const MetricSampling& sampling);

}  // namespace maxillo
