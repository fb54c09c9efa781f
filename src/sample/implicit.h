#pragma once
// Implicit primitives for the phantom: inside tests on points of the patient LPS frame (mm).
// The phantom is painted part by part, so only "is this point inside?" is needed, never a
// true signed distance. "a" below is the anterior coordinate a = -y (the face looks towards -y).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <span>

namespace maxillo::sample {

using Eigen::Vector2d;
using Eigen::Vector3d;

// An LPS point from (x left, a anterior, z superior).
inline Vector3d lps(double x, double a, double z) { return {x, -a, z}; }
inline double anterior(const Vector3d& p) { return -p.y(); }

inline double lerp(double from, double to, double t) { return from + (to - from) * t; }
// 0 below edge0, 1 above edge1, smooth (C1) in between; edge0 > edge1 gives a falling step.
inline double smoothstep(double edge0, double edge1, double v) {
  double t = std::clamp((v - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// Axis-aligned box in LPS used to limit where a part is evaluated.
struct Box {
  Vector3d lo, hi;
  static Box spanning(const Vector3d& a, const Vector3d& b) { return {a.cwiseMin(b), a.cwiseMax(b)}; }
  static Box around(const Vector3d& centre, const Vector3d& half) { return {centre - half, centre + half}; }
  Box mirrored_x() const { return {{-hi.x(), lo.y(), lo.z()}, {-lo.x(), hi.y(), hi.z()}}; }
  Box united(const Box& o) const { return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)}; }
  bool contains(const Vector3d& p) const { return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all(); }
};

// Axis-aligned ellipsoid.
inline bool in_ellipsoid(const Vector3d& p, const Vector3d& centre, const Vector3d& semi_axes) {
  return ((p - centre).cwiseQuotient(semi_axes)).squaredNorm() < 1.0;
}
inline Box ellipsoid_box(const Vector3d& centre, const Vector3d& semi_axes) { return Box::around(centre, semi_axes); }

// Distance from p to the segment [a, b].
inline double segment_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  Vector3d ab = b - a;
  double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}
// Capsule whose radius varies linearly from ra at a to rb at b (a "round cone" test).
inline bool in_tapered_capsule(const Vector3d& p, const Vector3d& a, const Vector3d& b, double ra, double rb) {
  Vector3d ab = b - a;
  double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm() < lerp(ra, rb, t);
}
inline Box capsule_box(const Vector3d& a, const Vector3d& b, double r) {
  Vector3d pad(r, r, r);
  return {a.cwiseMin(b) - pad, a.cwiseMax(b) + pad};
}

// Even-odd point-in-polygon test in 2D.
inline bool in_polygon(const Vector2d& q, std::span<const Vector2d> vertices) {
  bool inside = false;
  for (size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
    const Vector2d& vi = vertices[i];
    const Vector2d& vj = vertices[j];
    if ((vi.y() > q.y()) != (vj.y() > q.y()) &&
        q.x() < (vj.x() - vi.x()) * (q.y() - vi.y()) / (vj.y() - vi.y()) + vi.x())
      inside = !inside;
  }
  return inside;
}

// Superellipse |u/hu|^n + |v/hv|^n < 1: a rounded rectangle for n ~ 4, an ellipse for n = 2.
inline bool in_superellipse(double u, double v, double hu, double hv, double n) {
  if (hu <= 0 || hv <= 0) return false;
  return std::pow(std::abs(u / hu), n) + std::pow(std::abs(v / hv), n) < 1.0;
}

}  // namespace maxillo::sample
