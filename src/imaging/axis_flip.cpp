#include "imaging/axis_flip.h"

namespace maxillo {

std::optional<Eigen::Matrix3d> axis_flip_correction(const HeadOrientation& found) {
  if (!found.contradicts_header() || found.sideways) return std::nullopt;
  const double y = found.face == AxisVerdict::kReversed ? -1 : 1;
  const double z = found.vertex == AxisVerdict::kReversed ? -1 : 1;
  return Eigen::Vector3d(1, y, z).asDiagonal().toDenseMatrix();
}

Eigen::Vector3d grid_centre(const VolumeGeometry& geometry) {
  return geometry.world(0.5 * (geometry.size - Eigen::Vector3i::Ones()).cast<double>());
}

VolumeGeometry flipped_about_centre(const VolumeGeometry& geometry, const Eigen::Matrix3d& flip) {
  const Eigen::Vector3d centre = grid_centre(geometry);
  VolumeGeometry flipped = geometry;
  flipped.direction = flip * geometry.direction;
  flipped.origin = centre + flip * (geometry.origin - centre);
  return flipped;
}

}  // namespace maxillo
