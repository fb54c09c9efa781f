#pragma once
// A CT of real teeth in occlusion (issue 30's test of dental scan registration against what a CT
// shows, not against the teeth's own surfaces): the two arches (closed, outward-oriented, one
// frame) voxelised with partial volume at their surfaces, enamel at each arch's biting end and
// dentine below it, a shell of alveolar bone around the roots, soft tissue elsewhere; metal
// fillings on the back teeth throwing bright and dark streaks across their slices, as amalgam
// does in a CT; noise. A threshold between bone and dentine then finds the teeth with their
// roots, the streaks' brightest parts and the fillings: the surface a registration must live with.
#include <cstdint>

#include "core/triangle_mesh.h"
#include "core/volume.h"

namespace maxillo {

struct TeethCtOptions {
  double spacing_mm = 0.4;  // a cone-beam CT's voxel
  double margin_mm = 6;     // around the teeth
  double enamel_hu = 2500, dentine_hu = 1800, bone_hu = 900, soft_tissue_hu = 40;
  double crown_height_mm = 8;  // enamel from each arch's biting end (along the arches' axis)
  double bone_shell_mm = 2;    // alveolar bone around the roots
  int fillings = 3;            // on the back teeth: both sides of the upper arch, one of the lower
  double filling_radius_mm = 1.5;
  double streak_hu = 1500;  // a streak's contrast 5 mm from its filling (it falls off with distance)
  double noise_hu = 30;     // standard deviation
  uint32_t seed = 1;
  int max_threads = 0;  // slices run on this many threads (<= 0: the machine's cores); the volume is the same
};

Volume teeth_ct(const TriangleMesh& upper, const TriangleMesh& lower, const TeethCtOptions& options = {});

}  // namespace maxillo
