#include "sample/phantom_landmarks.h"

#include <cassert>

#include "sample/phantom_dentition.h"
#include "sample/phantom_mandible.h"
#include "sample/phantom_skin.h"

namespace maxillo::sample {
namespace {

constexpr double kOrbitaleX = 33;  // centre of the orbital opening
constexpr double kPorionA = -20;   // ear canal axis (phantom_cavities.cpp)

// First point of `tissue` on the ray from `outside` along `direction` (unit), to 1e-4 mm.
Vector3d first_hit(const PartList& parts, Tissue tissue, const Vector3d& outside, const Vector3d& direction) {
  auto hit = [&](double t) { return sample_parts(parts, outside + t * direction).tissue == tissue; };
  double step = 0.25, t = 0;
  while (!hit(t + step)) {
    t += step;
    assert(t < 200 && "phantom landmark ray missed its structure");
    if (t > 200) return outside;
  }
  double lo = t, hi = t + step;
  while (hi - lo > 1e-4) {
    double mid = (lo + hi) / 2;
    (hit(mid) ? hi : lo) = mid;
  }
  return outside + hi * direction;
}

Vector3d mirrored(const Vector3d& p) { return {-p.x(), p.y(), p.z()}; }

// Subnasale, where the columella meets the upper lip: the bottom of the skin's concavity between
// pronasale and labrale superius, the midline point farthest behind the line joining them
// (sampled every 0.01 mm of height). The lip below is nearly upright, so "the deepest point"
// along one axis would depend on the head's pitch; the depth behind that line does not.
Vector3d subnasale(const SkinProfile& skin) {
  const Eigen::Vector2d prn(kPronasaleHeight, skin.midline(kPronasaleHeight));
  const Eigen::Vector2d ls(kLabraleSuperiusHeight, skin.midline(kLabraleSuperiusHeight));
  const Eigen::Vector2d along = (prn - ls).normalized();
  double deepest = -1, best_z = kSubnasaleHeight;
  for (double z = ls.x(); z <= prn.x(); z += 0.01) {
    const Eigen::Vector2d p(z, skin.midline(z));
    const Eigen::Vector2d off = p - ls;
    const double behind = along.x() * off.y() - along.y() * off.x();  // towards smaller a: behind the line
    if (-behind > deepest) deepest = -behind, best_z = z;
  }
  return lps(0, skin.midline(best_z), best_z);
}

// Articulare as the field defines it on a lateral cephalogram: where the shadow of the condylar
// process's posterior border crosses the inferior contour of the cranial base (the
// basiocciput's). In 3D: the point of the posterior border, read in the ramus's mid-plane, at
// the height where the underside of the cranial base at the midline (read upwards from the
// pharynx) lies at the same depth. The border is nearly upright there and the base's underside
// nearly level, so the crossing is well defined in both directions, unlike the border's most
// posterior point, which a nearly straight border leaves undefined in height (issue 28).
constexpr double kBaseReadFromZ = -24;  // below the sphenoid's underside, above the dens (phantom_neck.cpp)
Vector3d articulare(const PartList& parts, Side side) {
  const double sign = side == Side::kLeft ? 1 : -1;
  auto border_at = [&](double z) {
    return first_hit(parts, Tissue::kMandible, lps(sign * ramus_mid_plane_x(z), -40, z), Vector3d(0, -1, 0));
  };
  auto base_underside_at = [&](double a) {
    return first_hit(parts, Tissue::kBone, lps(0, a, kBaseReadFromZ), Vector3d(0, 0, 1)).z();
  };
  // The border rises to meet the base: below the crossing it lies beneath the base's underside.
  auto below_base = [&](double z) { return z < base_underside_at(anterior(border_at(z))); };
  double lo = -20, hi = -1;  // the condylar neck and head (the condyle's top lies at z = 0)
  assert(below_base(lo) && !below_base(hi) && "phantom articulare: the border does not cross the base");
  while (hi - lo > 1e-4) {
    const double mid = (lo + hi) / 2;
    (below_base(mid) ? lo : hi) = mid;
  }
  return border_at(hi);
}

}  // namespace

LandmarkSet phantom_landmarks(const PhantomDesign& d, const PartList& parts) {
  const Dentition teeth(d);
  const SkinProfile skin(d);
  LandmarkSet set;
  auto add = [&set](const char* label, const Vector3d& p) { set.push_back({label, p}); };
  auto skin_point = [&skin](double z) { return lps(0, skin.midline(z), z); };

  add("S", d.S);
  add("N", d.N);
  Vector3d or_left = first_hit(parts, Tissue::kBone, lps(kOrbitaleX, 100, 0), Vector3d(0, 1, 0));
  add("OrR", mirrored(or_left));
  add("OrL", or_left);
  Vector3d po_left = first_hit(parts, Tissue::kBone, lps(90, kPorionA, 0), Vector3d(-1, 0, 0));
  add("PoR", mirrored(po_left));
  add("PoL", po_left);
  add("A", d.from_maxilla_reference(d.A));
  add("B", d.from_mandible_reference(d.B));
  add("ANS", d.from_maxilla_reference(d.ANS));
  add("PNS", d.from_maxilla_reference(d.PNS));
  add("Pog", d.from_mandible_reference(d.Pog));
  add("Me", d.from_mandible_reference(d.Me));
  add("Gn", d.from_mandible_reference(d.Gn));
  add("GoR", d.from_mandible_reference(gonion(d, Side::kRight)));
  add("GoL", d.from_mandible_reference(gonion(d, Side::kLeft)));
  add("ArR", articulare(parts, Side::kRight));
  add("ArL", articulare(parts, Side::kLeft));
  add("U1", teeth.incisal_edge_centre(Jaw::kUpper, Side::kRight));
  add("L1", teeth.incisal_edge_centre(Jaw::kLower, Side::kRight));
  add("U6R", teeth.mesiobuccal_cusp_tip(Jaw::kUpper, Side::kRight));
  add("U6L", teeth.mesiobuccal_cusp_tip(Jaw::kUpper, Side::kLeft));
  add("L6R", teeth.mesiobuccal_cusp_tip(Jaw::kLower, Side::kRight));
  add("L6L", teeth.mesiobuccal_cusp_tip(Jaw::kLower, Side::kLeft));
  add("Prn", skin_point(kPronasaleHeight));
  add("Sn", subnasale(skin));
  add("Ls", skin_point(kLabraleSuperiusHeight));
  add("Li", skin_point(kLabraleInferiusHeight));
  add("PogS", skin_point(d.from_mandible_reference(d.Pog).z()));
  add("NS", skin_point(d.N.z()));
  return set;
}

}  // namespace maxillo::sample
