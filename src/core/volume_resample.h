#pragma once
// A volume moved rigidly and sampled on another grid. Plain C++/Eigen (no ITK).
//
// result(x) = source(source_to_result^-1 * x) for every voxel centre x of result_geometry (LPS mm):
// a point p of the source appears at source_to_result * p in the result.
//   Volume:      trilinear interpolation between the 8 source voxels around the point; points
//                outside the box of the source's voxel centres (nothing to interpolate between)
//                get outside_hu; HU rounded to the nearest integer.
//   LabelVolume: nearest voxel; outside -> 0 (background).
#include <Eigen/Geometry>
#include <cstdint>

#include "core/volume.h"

namespace maxillo {

Volume resample_rigid(const Volume& source, const Eigen::Isometry3d& source_to_result,
                      const VolumeGeometry& result_geometry, int16_t outside_hu = -1000);

LabelVolume resample_rigid(const LabelVolume& source, const Eigen::Isometry3d& source_to_result,
                           const VolumeGeometry& result_geometry);

// The same interpolations at one LPS point (not rounded): for callers that build a volume from
// several sources point by point.
double sample_trilinear(const Volume& source, const Eigen::Vector3d& lps, double outside_hu = -1000);
uint8_t sample_nearest(const LabelVolume& source, const Eigen::Vector3d& lps);

}  // namespace maxillo
