#include "geometry/triangle_geometry.h"

#include <algorithm>
#include <array>

namespace maxillo {
namespace {

using Eigen::Vector3d;

// True when projections of p and q on `axis` are disjoint (a strict gap: touching is contact).
// The gap must exceed a rounding tolerance scaled by the coordinates involved, so that
// touching configurations computed in floating point are not declared separate by noise.
bool separated_on(const Vector3d& axis, const Triangle& p, const Triangle& q, double scale) {
  const double length = axis.norm();
  if (length <= 1e-14 * scale * scale) return false;
  const Vector3d unit = axis / length;
  const std::array<double, 3> dp{unit.dot(p.a), unit.dot(p.b), unit.dot(p.c)};
  const std::array<double, 3> dq{unit.dot(q.a), unit.dot(q.b), unit.dot(q.c)};
  const auto [pmin, pmax] = std::minmax({dp[0], dp[1], dp[2]});
  const auto [qmin, qmax] = std::minmax({dq[0], dq[1], dq[2]});
  const double tolerance = 1e-12 * scale;
  return pmax < qmin - tolerance || qmax < pmin - tolerance;
}

double coordinate_scale(const Triangle& p, const Triangle& q) {
  double scale = 1.0;
  for (const Vector3d* v : {&p.a, &p.b, &p.c, &q.a, &q.b, &q.c}) scale = std::max(scale, v->cwiseAbs().maxCoeff());
  return scale;
}

ClosestPoint closest_on_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b, TriangleFeature edge) {
  const Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return {a + s * ab, edge};
}

// Degenerate triangles: the nearest of the three edges.
ClosestPoint closest_point_on_edges(const Vector3d& p, const Triangle& t) {
  std::array<ClosestPoint, 3> candidates{closest_on_segment(p, t.a, t.b, TriangleFeature::EdgeAB),
                                         closest_on_segment(p, t.b, t.c, TriangleFeature::EdgeBC),
                                         closest_on_segment(p, t.c, t.a, TriangleFeature::EdgeCA)};
  return *std::min_element(candidates.begin(), candidates.end(), [&](const auto& x, const auto& y) {
    return (x.point - p).squaredNorm() < (y.point - p).squaredNorm();
  });
}

}  // namespace

bool triangles_intersect(const Triangle& p, const Triangle& q) {
  const double scale = coordinate_scale(p, q);
  const std::array<Vector3d, 3> ep{p.b - p.a, p.c - p.b, p.a - p.c};
  const std::array<Vector3d, 3> eq{q.b - q.a, q.c - q.b, q.a - q.c};
  const Vector3d np = ep[0].cross(ep[1]);
  const Vector3d nq = eq[0].cross(eq[1]);
  if (separated_on(np, p, q, scale) || separated_on(nq, p, q, scale)) return false;
  for (const Vector3d& e : ep)
    for (const Vector3d& f : eq)
      if (separated_on(e.cross(f), p, q, scale)) return false;
  for (const Vector3d& e : ep)
    if (separated_on(np.cross(e), p, q, scale)) return false;
  for (const Vector3d& f : eq)
    if (separated_on(nq.cross(f), p, q, scale)) return false;
  // Axes of the flat triangles' degenerate prism edges: needed only when edges are parallel.
  for (const Vector3d& e : ep)
    if (separated_on(e.cross(nq), p, q, scale)) return false;
  for (const Vector3d& f : eq)
    if (separated_on(np.cross(f), p, q, scale)) return false;
  return !separated_on(np.cross(nq), p, q, scale);
}

ClosestPoint closest_point_on_triangle(const Eigen::Vector3d& p, const Triangle& t) {
  const Vector3d ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {t.a, TriangleFeature::VertexA};
  const Vector3d bp = p - t.b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {t.b, TriangleFeature::VertexB};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return {t.a + d1 / (d1 - d3) * ab, TriangleFeature::EdgeAB};
  const Vector3d cp = p - t.c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {t.c, TriangleFeature::VertexC};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return {t.a + d2 / (d2 - d6) * ac, TriangleFeature::EdgeCA};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return {t.b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (t.c - t.b), TriangleFeature::EdgeBC};
  const double denominator = va + vb + vc;
  if (denominator <= 0) return closest_point_on_edges(p, t);  // zero-area triangle
  const double v = vb / denominator, w = vc / denominator;
  return {t.a + ab * v + ac * w, TriangleFeature::Face};
}

}  // namespace maxillo
