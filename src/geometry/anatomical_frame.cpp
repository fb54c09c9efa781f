#include "geometry/anatomical_frame.h"

#include <Eigen/Geometry>

namespace maxillo {
namespace {

constexpr double kMinPorionDistanceMm = 20;

std::optional<Eigen::Vector3d> mean_of_present(const std::optional<Eigen::Vector3d>& a,
                                               const std::optional<Eigen::Vector3d>& b) {
  if (a && b) return 0.5 * (*a + *b);
  if (a) return a;
  return b;
}

}  // namespace

AnatomicalFrame frankfort_frame(const FrankfortPoints& points) {
  const auto& po_r = points.porion_right;
  const auto& po_l = points.porion_left;
  const auto& or_r = points.orbitale_right;
  const auto& or_l = points.orbitale_left;
  const auto orbitale = mean_of_present(or_r, or_l);
  if (!po_r || !po_l || !orbitale) return AnatomicalFrame{};
  const Eigen::Vector3d transverse = *po_l - *po_r;
  if (transverse.norm() < kMinPorionDistanceMm) return AnatomicalFrame{};
  Eigen::Vector3d left = transverse.normalized();
  if (or_r && or_l && (*or_l - *or_r).norm() > kMinPorionDistanceMm / 2)
    left = (left + (*or_l - *or_r).normalized()).normalized();

  AnatomicalFrame frame;
  frame.origin = 0.5 * (*po_r + *po_l);
  const Eigen::Vector3d forward = *orbitale - frame.origin;
  const Eigen::Vector3d superior = forward.cross(left);
  // Orbitales must lie well in front of the porions, not along the transverse axis.
  if (superior.norm() < 0.5 * forward.norm()) return AnatomicalFrame{};
  frame.left = left;
  frame.superior = superior.normalized();
  frame.anterior = frame.left.cross(frame.superior);
  frame.source = FrameSource::Frankfort;
  return frame;
}

}  // namespace maxillo
