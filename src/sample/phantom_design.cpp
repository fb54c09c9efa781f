#include "sample/phantom_design.h"

#include <numbers>

#include "core/angles.h"

namespace maxillo::sample {
namespace {

// Palate and nasal spine (mm).
constexpr double kAnsAnterior = 72.5, kAnsHeight = -24;  // anterior nasal spine tip
constexpr double kPnsAnterior = 19.5, kPnsHeight = -25;  // posterior nasal spine tip (ANS-PNS 53)
// Upper alveolar front: a(z) = A.a + k (z - A.z)^2 (prosthion ~1 mm labial of the incisor roots).
constexpr double kUpperAlveolarCurvature = 0.035;  // 1/mm
// Lower alveolar front: deepest at B, steeper above B (alveolus) than below (chin).
constexpr double kLowerAlveolarCurvatureAbove = 0.052, kLowerAlveolarCurvatureBelow = 0.0208;
constexpr double kPogBelowB = 12;  // Pog lies 12 mm below B
// Occlusal plane: through the incisor overlap (a = 70, z = -50.75), tilted kOcclusalTilt.
constexpr double kOcclusalAnterior = 70, kOcclusalHeight = -50.75;

// The point at `length` from `origin` in the mid-sagittal plane, in the direction `angle_deg`
// measured from anterior (+a) towards superior (+z).
Vector3d point_from(const Vector3d& origin, double length, double angle_deg) {
  const Vector3d direction = lps(0, std::cos(angle_deg * kDeg), std::sin(angle_deg * kDeg));
  return origin + length * direction;
}

}  // namespace

double PhantomDesign::occlusal_z(double a) const {
  return occlusal_origin.z() + (anterior(occlusal_origin) - a) * std::tan(kOcclusalTilt * kDeg);
}

double PhantomDesign::palatal_z(double a) const {
  double t = (a - anterior(PNS)) / (anterior(ANS) - anterior(PNS));
  return lerp(PNS.z(), ANS.z(), t);
}

double PhantomDesign::upper_alveolar_front(double z) const {
  double dz = z - A.z();
  return anterior(A) + kUpperAlveolarCurvature * dz * dz;
}

double PhantomDesign::lower_alveolar_front(double z) const {
  double dz = z - B.z();
  double k = dz > 0 ? kLowerAlveolarCurvatureAbove : kLowerAlveolarCurvatureBelow;
  return anterior(B) + k * dz * dz;
}

double PhantomDesign::maxilla_weight(double z) { return smoothstep(kLeFortLevel + 4, kLeFortLevel - 4, z); }
double PhantomDesign::mandible_weight(double a) { return smoothstep(10, 40, a); }

Vector3d PhantomDesign::to_maxilla_reference(const Vector3d& p) const {
  return {p.x(), p.y() + maxilla_shift * maxilla_weight(p.z()), p.z()};
}
Vector3d PhantomDesign::from_maxilla_reference(const Vector3d& p) const {
  return {p.x(), p.y() - maxilla_shift * maxilla_weight(p.z()), p.z()};
}

Vector3d PhantomDesign::to_mandible_reference(const Vector3d& p) const {
  // Invert a_ref + shift * w(a_ref) = a by fixed-point iteration (contraction: shift * w' < 1).
  double a = anterior(p), a_ref = a;
  for (int i = 0; i < 6; ++i) a_ref = a - mandible_shift * mandible_weight(a_ref);
  return {p.x() - mandible_deviation * mandible_weight(a_ref), -a_ref, p.z()};
}
Vector3d PhantomDesign::from_mandible_reference(const Vector3d& p) const {
  const double w = mandible_weight(anterior(p));
  return {p.x() + mandible_deviation * w, p.y() - mandible_shift * w, p.z()};
}

PhantomDesign make_design(const PhantomSpec& spec) {
  PhantomDesign d;
  d.maxilla_shift = spec.maxillary_advancement_mm;
  d.mandible_shift = spec.mandibular_protrusion_mm;
  d.mandible_deviation = spec.mandibular_deviation_mm;
  d.S = lps(0, 0, kSellaHeight);
  d.N = point_from(d.S, kSellaNasion, kSnToFrankfort);
  // Ray N->S points at 180 + 7 deg; A and B are reached by turning towards inferior.
  d.A = point_from(d.N, kNasionToA, 180 + kSnToFrankfort + kSna);
  d.B = point_from(d.N, kNasionToB, 180 + kSnToFrankfort + kSnb);
  d.ANS = lps(0, kAnsAnterior, kAnsHeight);
  d.PNS = lps(0, kPnsAnterior, kPnsHeight);
  double pog_z = d.B.z() - kPogBelowB;
  d.Pog = lps(0, d.lower_alveolar_front(pog_z), pog_z);
  double chin_centre_a = anterior(d.Pog) - kChinDepth;
  d.Me = lps(0, chin_centre_a, pog_z - kChinHeight);
  // Gnathion: the chin outline point whose outward normal points 45 deg antero-inferiorly.
  double t = -std::atan(kChinHeight / kChinDepth);
  d.Gn = lps(0, chin_centre_a + kChinDepth * std::cos(t), pog_z + kChinHeight * std::sin(t));
  d.occlusal_origin = lps(0, kOcclusalAnterior, kOcclusalHeight);
  d.occlusal_normal = lps(0, std::sin(kOcclusalTilt * kDeg), std::cos(kOcclusalTilt * kDeg));
  return d;
}

}  // namespace maxillo::sample
