#pragma once
// The implicit solid of a surgical splint (issue 6 item 6): an occlusal wafer between the arches
// in their final occlusion that carries the imprints of both. On a grid aligned with the occlusal
// plane, the splint is the intersection of
//   - a slab around the occlusal plane (thickness_mm + 2 x imprint_depth_mm thick),
//   - a band along the dental arch: the teeth's outline in the plane widened by margin_mm
//     (so the wafer follows the U of the arch instead of filling the palate),
//   - the outside of each arch grown by clearance_mm (the imprints),
// written as a field that is positive inside the splint: the minimum of the four signed
// distances. Its zero iso-surface (marching cubes, pipeline/surgical_splint.h) is the splint;
// a field rather than a 0/1 mask gives imprints that follow the teeth within a few hundredths
// of a millimetre instead of a voxel staircase.
#include <Eigen/Geometry>
#include <vector>

#include "core/volume.h"
#include "geometry/signed_distance.h"

namespace maxillo::occlusion {

struct SplintOptions {
  double thickness_mm = 2.0;      // minimum thickness where no tooth is
  double imprint_depth_mm = 1.0;  // how far the wafer reaches into each arch beyond that
  double clearance_mm = 0.1;      // gap left around the teeth (seating, scan noise)
  double margin_mm = 3.0;         // the band extends this far beyond the teeth's outline
  double voxel_mm = 0.25;         // grid spacing of the field
  double plane_region_mm = 2.0;   // vertices this close to the other arch fit the occlusal plane
};

// A plane through `centre` with unit `normal` pointing towards the upper arch; `u`, `v` span it.
struct OcclusalPlane {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY();
};

// Least-squares plane (principal axes) through the vertices of both arches that lie within
// region_mm of the other arch at `upper_pose` (the occlusal surfaces), normal towards the upper
// arch. Throws Error(kProcessing) when fewer than 3 such vertices exist (the arches are apart).
OcclusalPlane fit_occlusal_plane(const DistanceField& upper, const DistanceField& lower,
                                 const Eigen::Isometry3d& upper_pose, double region_mm);

struct SplintField {
  OcclusalPlane plane;
  // Field value in micrometres (positive inside the splint), on a grid whose i, j, k axes are
  // the plane's u, v and normal: extract the surface at iso 0.
  Volume field;
  // Grid columns (i + size.x * j) inside the band whose whole height stays farther than
  // clearance + one voxel from both arches: there the wafer has its full thickness.
  std::vector<int> tooth_free_columns;
  double slab_half_thickness_mm = 0;
};

// The field in the lower arch's frame (upper placed by upper_pose).
SplintField splint_field(const DistanceField& upper, const DistanceField& lower, const Eigen::Isometry3d& upper_pose,
                         const SplintOptions& options = {});

// Exact Euclidean distance (in pixels) from every pixel of a width x height image to the nearest
// marked pixel (Felzenszwalb & Huttenlocher 2012); +infinity when nothing is marked.
std::vector<double> distance_to_marked(const std::vector<char>& marked, int width, int height);

}  // namespace maxillo::occlusion
