#include "ceph/cephalometric_measures.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "core/angles.h"

namespace maxillo::ceph {
namespace {

Eigen::Vector2d rotated(const Eigen::Vector2d& v, double radians) {
  double c = std::cos(radians), s = std::sin(radians);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}
}  // namespace

double angle_at_deg(const Eigen::Vector2d& vertex, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Eigen::Vector2d u = a - vertex, v = b - vertex;
  assert(u.norm() > 0 && v.norm() > 0 && "angle with a zero-length ray");
  // atan2 of cross and dot: accurate near 0 and 180 deg, unlike acos.
  double cross = u.x() * v.y() - u.y() * v.x();
  return std::atan2(std::abs(cross), u.dot(v)) / kDeg;
}

double sna_deg(const Eigen::Vector2d& S, const Eigen::Vector2d& N, const Eigen::Vector2d& A) {
  return angle_at_deg(N, S, A);
}
double snb_deg(const Eigen::Vector2d& S, const Eigen::Vector2d& N, const Eigen::Vector2d& B) {
  return angle_at_deg(N, S, B);
}
double anb_deg(const Eigen::Vector2d& S, const Eigen::Vector2d& N, const Eigen::Vector2d& A, const Eigen::Vector2d& B) {
  return sna_deg(S, N, A) - snb_deg(S, N, B);
}

double wits_mm(const Eigen::Vector2d& A, const Eigen::Vector2d& B, const Eigen::Vector2d& occlusal_posterior,
               const Eigen::Vector2d& occlusal_anterior) {
  Eigen::Vector2d direction = occlusal_anterior - occlusal_posterior;
  assert(direction.norm() > 0 && "occlusal line needs two distinct points");
  direction.normalize();
  return (A - B).dot(direction);
}

NasionFrame nasion_frame(const Eigen::Vector2d& S, const Eigen::Vector2d& N) {
  Eigen::Vector2d sn = N - S;
  assert(sn.norm() > 0 && "S and N coincide");
  // Sagittal frame: u anterior, v superior; a negative (clockwise) rotation lowers the anterior end.
  Eigen::Vector2d x_axis = rotated(sn.normalized(), -kNasionFrameRotationDeg * kDeg);
  Eigen::Vector2d y_axis = rotated(x_axis, -90 * kDeg);  // anterior -> inferior
  return {N, x_axis, y_axis};
}

Eigen::Vector2d in_nasion_frame(const NasionFrame& frame, const Eigen::Vector2d& p) {
  Eigen::Vector2d d = p - frame.origin;
  return {d.dot(frame.x_axis), d.dot(frame.y_axis)};
}

double palatal_angle_alpha_deg(const NasionFrame& frame, const Eigen::Vector2d& ANS, const Eigen::Vector2d& PNS) {
  Eigen::Vector2d d = in_nasion_frame(frame, ANS) - in_nasion_frame(frame, PNS);
  return std::atan2(d.x(), d.y()) / kDeg;
}

}  // namespace maxillo::ceph
