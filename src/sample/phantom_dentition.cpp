#include "sample/phantom_dentition.h"

#include <array>
#include <cassert>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/angles.h"
#include "sample/phantom_parts.h"

namespace maxillo::sample {
namespace {

struct ToothDims {
  double width, crown_height, thickness, root_length;
  int roots;
  double torque_deg;   // crown tipped labially from the occlusal normal
  double edge_offset;  // incisal edge beyond the occlusal plane (mm, towards the other arch)
};
// Adult mesio-distal widths, crown heights, labio-lingual thicknesses and root lengths (mm).
constexpr std::array<ToothDims, 7> kUpperTeeth = {{{8.5, 10.5, 7.0, 13, 1, 28, 1.1},
                                                   {6.5, 9.0, 6.0, 13, 1, 26, 0},
                                                   {7.5, 10.0, 8.0, 15, 1, 12, 0},
                                                   {7.0, 8.5, 9.0, 13, 1, 0, 0},
                                                   {6.5, 8.0, 9.0, 13, 1, 0, 0},
                                                   {10.0, 7.0, 11.0, 10, 3, 0, 0},
                                                   {9.0, 6.5, 10.5, 10, 3, 0, 0}}};
constexpr std::array<ToothDims, 7> kLowerTeeth = {{{5.0, 9.0, 6.0, 12.5, 1, 20, 1.1},
                                                   {5.5, 9.0, 6.0, 13.5, 1, 20, 0},
                                                   {7.0, 11.0, 7.5, 15, 1, 12, 0},
                                                   {7.0, 8.5, 7.5, 14, 1, 0, 0},
                                                   {7.0, 8.0, 8.0, 14.5, 1, 0, 0},
                                                   {11.0, 7.5, 10.5, 14, 2, 0, 0},
                                                   {10.5, 7.0, 10.0, 13, 2, 0, 0}}};
constexpr double kFossaDepth = 1.0;  // central fossa below the cusp tips (mm)
// How far the lower central incisors' edges may come forward of their Class I place before they
// would run into the upper ones (overjet about 3 mm less the upper edges' thickness).
constexpr double kIncisorClearanceMm = 0.5;

// A mandible brought forward of the maxilla beyond the clearance carries its central incisors
// into the upper ones. Patients compensate (the lower incisors stand more upright, Class III
// dento-alveolar compensation): the crown is tipped lingually about the root apex by as much
// as the excess, so that the incisors keep their overlap and never pass through each other.
double lingual_tip_of_lower_incisors(const PhantomDesign& design) {
  return std::max(0.0, design.mandible_shift - design.maxilla_shift - kIncisorClearanceMm);
}

// Point and unit tangent (distal) of the arch at arc length s from the midline, left side.
void arch_point(const ArchShape& arch, double s, Vector2d& point, Vector2d& tangent) {
  // March along the ellipse in small angle steps; the arch is ~60 mm long, 0.05 mm steps.
  double t = 0, length = 0;
  const double dt = 1e-4;
  const double power = 2 / arch.exponent;
  auto at = [&](double u) {
    return Vector2d(arch.half_width * std::pow(std::sin(u), power),
                    arch.front - arch.depth * (1 - std::pow(std::cos(u), power)));
  };
  Vector2d previous = at(0);
  while (length < s) {
    t += dt;
    Vector2d next = at(t);
    length += (next - previous).norm();
    previous = next;
  }
  point = previous;
  tangent = (at(t + dt) - at(std::max(0.0, t - dt))).normalized();
}

// Depth of the occlusal surface below the cusp-tip plane: zero at the four cusp tips
// (m, b) = (+-w/4, +-t/4), kFossaDepth in the central fossa.
double fossa(double m, double b, double width, double thickness) {
  double sm = std::sin(std::numbers::pi * m / (width / 2));
  double sb = std::sin(std::numbers::pi * b / (thickness / 2));
  return kFossaDepth * (1 - sm * sm * sb * sb);
}

}  // namespace

Dentition::Dentition(const PhantomDesign& design) : design_(design) {
  const Vector3d normal = design.occlusal_normal;
  for (Jaw jaw : {Jaw::kUpper, Jaw::kLower}) {
    const auto& dims = jaw == Jaw::kUpper ? kUpperTeeth : kLowerTeeth;
    const ArchShape& arch = jaw == Jaw::kUpper ? kUpperArch : kLowerArch;
    const Vector3d occlusal = jaw == Jaw::kUpper ? normal : Vector3d(-normal);  // crown -> root
    double s = 0;
    for (int i = 0; i < 7; ++i) {
      const ToothDims& d = dims[i];
      s += d.width / 2;
      Vector2d xa, tangent;
      arch_point(arch, s, xa, tangent);
      s += d.width / 2;
      for (Side side : {Side::kRight, Side::kLeft}) {
        double sign = side == Side::kLeft ? 1 : -1;
        double x = sign * xa.x(), a = xa.y();
        double z = design.occlusal_z(a) + (jaw == Jaw::kUpper ? -d.edge_offset : d.edge_offset);
        // Distal direction in the occlusal plane (follows the plane's anterior slope).
        Vector3d distal = Vector3d(sign * tangent.x(), -tangent.y(), 0);
        distal -= normal * normal.dot(distal);
        distal.normalize();
        // Outward (labial/buccal): in the plane, perpendicular to the arch, away from its centre.
        Vector3d outward = distal.cross(normal).normalized();
        if (outward.dot(lps(-sign * tangent.y(), tangent.x(), 0)) < 0) outward = -outward;
        // Torque: the root tips lingually (crown labially) by torque_deg.
        Vector3d apical = std::cos(d.torque_deg * kDeg) * occlusal - std::sin(d.torque_deg * kDeg) * outward;
        Vector3d edge = lps(x, a, z);
        double root_length = d.root_length;
        if (jaw == Jaw::kLower && i == 0) {
          // Tipped about the apex; the edge keeps its height (the root is a little shorter).
          const double length = d.crown_height + d.root_length, tip = lingual_tip_of_lower_incisors(design);
          const Vector3d apex = edge + length * apical;
          const double rise = length * std::cos(d.torque_deg * kDeg);  // apex to edge along the occlusal normal
          const double torque = std::atan(std::tan(d.torque_deg * kDeg) - tip / rise) / kDeg;
          apical = std::cos(torque * kDeg) * occlusal - std::sin(torque * kDeg) * outward;
          const double kept = rise / std::cos(torque * kDeg);
          edge = apex - kept * apical;
          root_length -= length - kept;
        }
        Vector3d buccal = (outward - apical * apical.dot(outward)).normalized();
        teeth_.push_back(Tooth{jaw, side, i + 1, edge, distal, buccal, apical.normalized(), occlusal, d.width,
                               d.crown_height, d.thickness, root_length, d.roots, i >= 3, i >= 1});
      }
    }
  }
}

const Tooth& Dentition::tooth(Jaw jaw, Side side, int position) const {
  for (const Tooth& t : teeth_)
    if (t.jaw == jaw && t.side == side && t.position == position) return t;
  assert(false && "no such tooth");
  return teeth_.front();
}

Vector3d Dentition::displaced(Jaw jaw, const Vector3d& reference) const {
  return jaw == Jaw::kUpper ? design_.from_maxilla_reference(reference) : design_.from_mandible_reference(reference);
}
Vector3d Dentition::reference_of(Jaw jaw, const Vector3d& p) const {
  return jaw == Jaw::kUpper ? design_.to_maxilla_reference(p) : design_.to_mandible_reference(p);
}

bool Dentition::inside_reference(const Tooth& t, ToothPart part, const Vector3d& p) const {
  Vector3d q = p - t.origin;
  double v = q.dot(t.apical), m = q.dot(t.mesiodistal), b = q.dot(t.buccal);
  if (part == ToothPart::kCrown) {
    if (v > t.crown_height) return false;
    double f = v / t.crown_height;
    if (t.posterior) {
      // Occlusal surface: measured from the occlusal plane along the normal (== apical here).
      if (v < fossa(m, b, t.width, t.thickness)) return false;
      double bulge = 1 - 0.15 * f * f;
      return in_superellipse(m, b, t.width / 2 * bulge, t.thickness / 2 * bulge, 3);
    }
    if (v < 0 || (t.cut_by_occlusal_plane && q.dot(t.into_jaw) < 0)) return false;
    double thickness = lerp(1.2, t.thickness, std::min(1.0, f / 0.7));
    double width = t.width * (1 - 0.2 * f);
    if (t.position == 3) width *= std::min(1.0, 0.35 + f / 0.4);  // canine cusp
    return in_superellipse(m, b, width / 2, thickness / 2, 3);
  }
  double r = (v - t.crown_height) / t.root_length;
  if (r < 0 || r > 1) return false;
  double taper = 1 - 0.8 * r;
  if (t.roots == 1) return in_superellipse(m, b, 0.35 * t.width * taper, 0.4 * t.thickness * taper, 2);
  // Molars: two (lower: mesial, distal) or three (upper: two buccal, one palatal) roots that
  // spread slightly towards their apices.
  const double spread = 1 + 0.3 * r;
  if (t.roots == 2) {
    for (double side : {-1.0, 1.0})
      if (in_superellipse(m - side * t.width / 4 * spread, b, 0.2 * t.width * taper, 0.35 * t.thickness * taper, 2))
        return true;
    return false;
  }
  const std::array<Vector2d, 3> centres = {Vector2d(-t.width / 4, t.thickness / 4),
                                           Vector2d(t.width / 4, t.thickness / 4), Vector2d(0, -t.thickness / 4)};
  for (const Vector2d& c : centres)
    if (in_superellipse(m - c.x() * spread, b - c.y() * spread, 0.18 * t.width * taper, 0.2 * t.thickness * taper, 2))
      return true;
  return false;
}

bool Dentition::inside(const Tooth& tooth, ToothPart part, const Vector3d& p) const {
  return inside_reference(tooth, part, reference_of(tooth.jaw, p));
}

bool Dentition::inside_upper(const Vector3d& p) const {
  Vector3d q = reference_of(Jaw::kUpper, p);
  for (const Tooth& t : teeth_)
    if (t.jaw == Jaw::kUpper && (inside_reference(t, ToothPart::kCrown, q) || inside_reference(t, ToothPart::kRoot, q)))
      return true;
  return false;
}

bool Dentition::inside_lower(const Vector3d& p) const {
  Vector3d q = reference_of(Jaw::kLower, p);
  for (const Tooth& t : teeth_)
    if (t.jaw == Jaw::kLower && (inside_reference(t, ToothPart::kCrown, q) || inside_reference(t, ToothPart::kRoot, q)))
      return true;
  return false;
}

Vector3d Dentition::incisal_edge_centre(Jaw jaw, Side side) const { return displaced(jaw, tooth(jaw, side, 1).origin); }

Vector3d Dentition::mesiobuccal_cusp_tip(Jaw jaw, Side side) const {
  const Tooth& t = tooth(jaw, side, 6);
  return displaced(jaw, t.origin - t.mesiodistal * (t.width / 4) + t.buccal * (t.thickness / 4));
}

void add_dentition_parts(const PhantomDesign& design, PartList& parts) {
  auto dentition = std::make_shared<Dentition>(design);
  for (const Tooth& t : dentition->teeth()) {
    // The tooth's oriented box (roots spread by up to 30 %), as an axis-aligned box.
    Box box{t.origin, t.origin};
    for (double u : {-0.7 * t.width, 0.7 * t.width})
      for (double v : {-0.6 * t.thickness, 0.6 * t.thickness})
        for (double w : {-1.0, t.crown_height + t.root_length + 0.5}) {
          Vector3d corner = t.origin + u * t.mesiodistal + v * t.buccal + w * t.apical;
          box = box.united({corner, corner});
        }
    double shift = std::abs(t.jaw == Jaw::kUpper ? design.maxilla_shift : design.mandible_shift);
    double deviation = t.jaw == Jaw::kUpper ? 0 : std::abs(design.mandible_deviation);
    box.lo.y() -= shift;
    box.hi.y() += shift;
    box.lo.x() -= deviation;
    box.hi.x() += deviation;
    Tissue tissue = t.jaw == Jaw::kUpper ? Tissue::kUpperTooth : Tissue::kLowerTooth;
    // Upper teeth replace maxillary bone, lower teeth mandibular bone; neither replaces the
    // other arch (with the knobs, incisors may meet: the upper arch wins).
    TissueMask over = t.jaw == Jaw::kUpper ? mask_of(Tissue::kAir, Tissue::kSoftTissue, Tissue::kBone)
                                           : mask_of(Tissue::kAir, Tissue::kSoftTissue, Tissue::kMandible);
    const Tooth* tooth = &t;
    parts.push_back({"tooth crown", box,
                     [dentition, tooth](const Vector3d& p) { return dentition->inside(*tooth, ToothPart::kCrown, p); },
                     tissue, Material::kEnamel, over});
    parts.push_back({"tooth root", box,
                     [dentition, tooth](const Vector3d& p) { return dentition->inside(*tooth, ToothPart::kRoot, p); },
                     tissue, Material::kDentine, over});
  }
}

void add_amalgam_fillings(const PhantomDesign& design, PartList& parts) {
  auto dentition = std::make_shared<Dentition>(design);
  for (Jaw jaw : {Jaw::kUpper, Jaw::kLower})
    for (Side side : {Side::kRight, Side::kLeft}) {
      const Tooth* tooth = &dentition->tooth(jaw, side, 6);
      // A class I cavity: an ellipsoid under the central fossa, 3.5 mm mesio-distally,
      // 2.5 mm bucco-lingually, 2 mm deep, inside the crown only (the cusp tips stay enamel).
      const Vector3d centre = tooth->origin + 1.2 * tooth->apical;
      auto inside = [dentition, tooth, jaw, centre](const Vector3d& p) {
        const Vector3d q = dentition->reference_of(jaw, p) - centre;
        const Vector3d local(q.dot(tooth->mesiodistal) / 1.75, q.dot(tooth->buccal) / 1.25, q.dot(tooth->apical) / 1.0);
        return local.squaredNorm() < 1 && dentition->inside(*tooth, ToothPart::kCrown, p);
      };
      double shift = std::abs(jaw == Jaw::kUpper ? design.maxilla_shift : design.mandible_shift) +
                     (jaw == Jaw::kUpper ? 0 : std::abs(design.mandible_deviation)) + 3;
      const Tissue tissue = jaw == Jaw::kUpper ? Tissue::kUpperTooth : Tissue::kLowerTooth;
      parts.push_back({"amalgam filling", Box::around(centre, Vector3d::Constant(shift)), inside, tissue,
                       Material::kAmalgam, mask_of(tissue)});
    }
}

}  // namespace maxillo::sample
