// Facial skeleton above the mandible: brow ridge, nasal bones, the bony core between the
// orbits around the nasal cavity, maxillary bodies, zygomas with their arches, the upper
// alveolar process, the hard palate and the anterior nasal spine. Everything is evaluated on
// the reference anatomy (maxillary displacement pulled back; it is zero above the Le Fort I band).
#include <memory>

#include "sample/phantom_parts.h"

namespace maxillo::sample {
namespace {

constexpr double kRhinionA = 80, kRhinionZ = 6;  // lower end of the nasal bones (midline)
constexpr double kGlabellaA = 71.5, kGlabellaZ = 38;
constexpr double kNasalSlope = 1.0;  // the nasal pyramid falls back 1 mm per mm laterally
constexpr double kNasalPyramidBack = 50;
// Bony core between the orbits and around the nasal cavity (ethmoid, frontal processes).
constexpr double kCoreHalfWidth = 22, kCoreBack = 20, kCoreFront = 66, kCoreFrontCurvature = 0.03;
constexpr double kCoreBottom = -24, kCoreTop = 36;
// Maxillary body (contains the sinus, see phantom_cavities.cpp), left side.
const Vector3d kMaxillaCentre = lps(28, 41, -11);
const Vector3d kMaxillaSemiAxes{16, 21.5, 18.5};
// Zygoma: body, frontal process (lateral orbital rim), arch to the temporal bone.
const Vector3d kZygomaCentre = lps(50, 46, -2);
const Vector3d kZygomaSemiAxes{9, 11, 12};
const Vector3d kZygomaFrontalFrom = lps(56, 50, 5), kZygomaFrontalTo = lps(53, 52, 36);
const Vector3d kZygomaticArchFrom = lps(52, 40, -2), kZygomaticArchTo = lps(62, -5, -2);
constexpr double kZygomaProcessRadius = 3.5;
// Brow ridge (supraorbital margin), left half.
const Vector3d kBrowFrom = lps(0, 66, 37), kBrowTo = lps(54, 50, 36);
constexpr double kBrowRadius = 4;
// Upper alveolar process: a U band between two concentric ellipses in the axial plane whose
// front (midline) follows upper_alveolar_front(z); from the crest up to kAlveolarTop.
constexpr double kAlveolarHalfWidth = 36, kAlveolarDepth = 46, kAlveolarWall = 12;
constexpr double kAlveolarBack = 19, kAlveolarTop = -20;
constexpr double kCrestAboveOcclusal = 9.5;  // alveolar crest above the occlusal plane
// Hard palate: nasal surface 2 mm above the palatal plane; the oral surface vaults down to
// the alveolar processes; rounded posterior edge whose tip is PNS.
constexpr double kPalateHalfThickness = 2, kPalateVault = 10;
constexpr double kNasalSpineRadius = 1.2, kNasalSpineBaseA = 66;

double nasal_line(const PhantomDesign& d, double z) {  // midline front of the nasal pyramid
  double n_a = anterior(d.N), n_z = d.N.z();
  if (z <= n_z) return n_a + (n_z - z) * (kRhinionA - n_a) / (n_z - kRhinionZ);
  return n_a + (z - n_z) * (kGlabellaA - n_a) / (kGlabellaZ - n_z);
}

// Is (x, a) inside the ellipse of semi-axes (half_width, depth) whose front is at a = front?
bool in_arch_ellipse(double x, double a, double front, double half_width, double depth) {
  double u = x / half_width, v = (a - (front - depth)) / depth;
  return u * u + v * v < 1;
}

}  // namespace

double nasal_bone_front(const PhantomDesign& design, double x, double z) {
  return nasal_line(design, z) - kNasalSlope * std::abs(x);
}

void add_midface_parts(const PhantomDesign& d, PartList& parts) {
  const TissueMask soft = mask_of(Tissue::kAir, Tissue::kSoftTissue);
  parts.push_back(bilateral(
      "brow ridge", capsule_box(kBrowFrom, kBrowTo, kBrowRadius),
      [](const Vector3d& p) { return segment_distance(p, kBrowFrom, kBrowTo) < kBrowRadius; }, Tissue::kBone,
      Material::kBone, soft));
  parts.push_back({"nasal bones", Box::spanning(lps(-20, kNasalPyramidBack, kRhinionZ), lps(20, 85, kGlabellaZ)),
                   [d](const Vector3d& p) {
                     double a = anterior(p);
                     return p.z() > kRhinionZ && p.z() < kGlabellaZ - 4 && a > kNasalPyramidBack &&
                            a < nasal_bone_front(d, p.x(), p.z());
                   },
                   Tissue::kBone, Material::kBone, soft});
  parts.push_back(with_maxilla(
      d, {"midface core",
          Box::spanning(lps(-kCoreHalfWidth, kCoreBack, kCoreBottom), lps(kCoreHalfWidth, kCoreFront, kCoreTop)),
          [](const Vector3d& p) {
            double a = anterior(p);
            return std::abs(p.x()) < kCoreHalfWidth && p.z() > kCoreBottom && p.z() < kCoreTop && a > kCoreBack &&
                   a < kCoreFront - kCoreFrontCurvature * p.x() * p.x();
          },
          Tissue::kBone, Material::kBone, soft}));
  parts.push_back(
      with_maxilla(d, bilateral(
                          "maxillary body", ellipsoid_box(kMaxillaCentre, kMaxillaSemiAxes),
                          [](const Vector3d& p) { return in_ellipsoid(p, kMaxillaCentre, kMaxillaSemiAxes); },
                          Tissue::kBone, Material::kBone, soft)));
  parts.push_back(with_maxilla(d, bilateral(
                                      "zygoma", ellipsoid_box(kZygomaCentre, kZygomaSemiAxes),
                                      [](const Vector3d& p) { return in_ellipsoid(p, kZygomaCentre, kZygomaSemiAxes); },
                                      Tissue::kBone, Material::kBone, soft)));
  parts.push_back(bilateral(
      "frontal process of the zygoma", capsule_box(kZygomaFrontalFrom, kZygomaFrontalTo, kZygomaProcessRadius),
      [](const Vector3d& p) {
        return segment_distance(p, kZygomaFrontalFrom, kZygomaFrontalTo) < kZygomaProcessRadius;
      },
      Tissue::kBone, Material::kBone, soft));
  parts.push_back(bilateral(
      "zygomatic arch", capsule_box(kZygomaticArchFrom, kZygomaticArchTo, kZygomaProcessRadius),
      [](const Vector3d& p) {
        return segment_distance(p, kZygomaticArchFrom, kZygomaticArchTo) < kZygomaProcessRadius;
      },
      Tissue::kBone, Material::kBone, soft));
  parts.push_back(with_maxilla(
      d, {"upper alveolar process",
          Box::spanning(lps(-kAlveolarHalfWidth, kAlveolarBack, -50), lps(kAlveolarHalfWidth, 80, kAlveolarTop)),
          [d](const Vector3d& p) {
            double a = anterior(p), z = p.z();
            if (a < kAlveolarBack || z > kAlveolarTop || z < d.occlusal_z(a) + kCrestAboveOcclusal) return false;
            double front = d.upper_alveolar_front(z);
            return a > front - kAlveolarDepth && in_arch_ellipse(p.x(), a, front, kAlveolarHalfWidth, kAlveolarDepth) &&
                   !in_arch_ellipse(p.x(), a, front - kAlveolarWall, kAlveolarHalfWidth - kAlveolarWall,
                                    kAlveolarDepth - kAlveolarWall);
          },
          Tissue::kBone, Material::kBone, soft}));
  parts.push_back(with_maxilla(
      d,
      {"hard palate", Box::spanning(lps(-kAlveolarHalfWidth, anterior(d.PNS), -40), lps(kAlveolarHalfWidth, 75, -18)),
       [d](const Vector3d& p) {
         double a = anterior(p), z = p.z();
         const double pns_a = anterior(d.PNS);
         // The palate fills the alveolar U (slightly overlapping its inner wall).
         double front = d.upper_alveolar_front(-26) - kAlveolarWall + 1.5;
         double half_width = kAlveolarHalfWidth - kAlveolarWall + 1.5, depth = kAlveolarDepth - kAlveolarWall + 1.5;
         double u = p.x() / half_width, v = (a - (front - depth)) / depth;
         if (u * u + v * v >= 1) return false;
         double mid = d.palatal_z(a);
         if (a < pns_a + kPalateHalfThickness) {  // rounded posterior edge, tip = PNS
           double da = a - (pns_a + kPalateHalfThickness), dz = z - d.palatal_z(pns_a);
           return da * da + dz * dz < kPalateHalfThickness * kPalateHalfThickness;
         }
         double lateral = std::min(1.0, u * u + v * v);
         return z < mid + kPalateHalfThickness && z > mid - kPalateHalfThickness - kPalateVault * lateral;
       },
       Tissue::kBone, Material::kBone, soft}));
  const Vector3d spine_base = lps(0, kNasalSpineBaseA, d.ANS.z());
  const Vector3d spine_end = d.ANS - lps(0, kNasalSpineRadius, 0);  // tip = ANS
  parts.push_back(with_maxilla(d, {"anterior nasal spine", capsule_box(spine_base, spine_end, kNasalSpineRadius),
                                   [spine_base, spine_end](const Vector3d& p) {
                                     return segment_distance(p, spine_base, spine_end) < kNasalSpineRadius;
                                   },
                                   Tissue::kBone, Material::kBone, soft}));
}

}  // namespace maxillo::sample
