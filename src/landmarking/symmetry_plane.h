#pragma once
// The midsagittal plane of a head from the symmetry of its bone: the plane about which the bone
// surface, mirrored, falls back onto itself. A skull is left-right symmetric to a few
// millimetres, which is what the field uses to define its midsagittal plane when no landmark
// is trusted yet.
//
// The bone surface is sampled as points; mirrored about a candidate plane, each point's distance
// to the nearest surface point (an exact Euclidean distance map of the surface, truncated so that
// asymmetric parts, a head rest or a dislocated jaw, weigh little) is averaged. A grid search over
// the plane's tilt (yaw and roll up to 24 degrees from the scan's sagittal plane) and offset
// finds the basin; a pattern search refines it to 0.01 degree and 0.01 mm. The distance map's
// voxels (1.5 mm) leave a bias of a few tenths of a millimetre, which the refinement on the grey
// values themselves removes.
#include <span>

#include <Eigen/Core>

#include "core/volume.h"
#include "imaging/grey_calibration.h"
#include "imaging/mask_grid.h"

namespace maxillo::landmarking {

struct Plane {
  Eigen::Vector3d normal{1, 0, 0};  // unit
  double offset = 0;                // normal . p = offset on the plane

  double signed_distance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
  Eigen::Vector3d mirrored(const Eigen::Vector3d& p) const { return p - 2 * signed_distance(p) * normal; }
};

// A surface as a distance map: the distance (mm) from each voxel of a regular axis-aligned grid
// to the nearest surface voxel, read with trilinear interpolation.
class SurfaceDistance {
 public:
  // `surface`: the surface voxels of `grid`, whose voxel (0,0,0) lies at `origin` (mm).
  SurfaceDistance(const Mask& surface, const MaskGrid& grid, const Eigen::Vector3d& origin);
  double at(const Eigen::Vector3d& p) const;

 private:
  std::vector<float> distance_;
  MaskGrid grid_;
  Eigen::Vector3d origin_;
};

struct SymmetryPlane {
  Plane plane;
  double mean_distance_mm = 0;  // of the mirrored points to the surface (truncated), the asymmetry
};

// `points`: samples of the bone surface; `surface`: its distance map; `initial`: the scan's
// sagittal plane through the bone's centre (normal +x). Deterministic.
SymmetryPlane find_symmetry_plane(std::span<const Eigen::Vector3d> points, const SurfaceDistance& surface,
                                  const Plane& initial);

// The plane refined on the scan's own grey values, to a fraction of a voxel: the summed absolute
// difference between the value at each point and at its mirror image (trilinear, clipped to
// -200..1600 HU so that neither air nor metal dominates) is made smallest. `points`: the bone
// surface (where the values change, so a misplaced plane costs most); `start`: the surface
// search's plane.
Plane refine_on_grey_values(const Volume& ct, const GreyCalibration& grey, std::span<const Eigen::Vector3d> points,
                            const Plane& start);

}  // namespace maxillo::landmarking
