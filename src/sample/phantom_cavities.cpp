// Cavities carved into the painted skeleton and soft tissue: orbits with the eyes, nasal
// cavity with septum and nostrils, maxillary sinuses, ear canals and the temporomandibular
// joint spaces. Each carve only replaces the tissues named in its mask.
#include "sample/phantom_parts.h"

namespace maxillo::sample {
namespace {

// Orbit (left): an elliptic cone from the opening (centre, half width, half height) back to the
// apex; in front of the opening it continues as a cylinder so the rim is where it meets bone.
// The opening's lowest point is at z = 0: the infraorbital margin, where Or lies. The outline
// holds for kOrbitRimDepth behind the opening (an orbit is widest just behind its margin), so
// the margin where the cavity meets the face (about 3 mm behind the opening at x = 33) has its
// lowest point at (33, z = 0) exactly, where phantom_landmarks.cpp places Or.
const Vector3d kOrbitOpening = lps(33, 60, 17.5);
const Vector3d kOrbitApex = lps(14, 15, 15);
constexpr double kOrbitHalfWidth = 20, kOrbitHalfHeight = 17.5;
constexpr double kOrbitRimDepth = 6;
const Vector3d kEyeCentre = lps(33, 50, 17.5);
constexpr double kEyeRadius = 12;
// Nasal cavity: width tapers from the floor (|x| < 12.5) to the roof (|x| < 5); from the
// choanae (a = 16, opening into the pharynx) to the piriform aperture (below the rhinion) or the nasal bones (above).
constexpr double kNasalBack = 16, kNasalRoof = 27, kNasalApertureFront = 69.5;
constexpr double kNasalFloorHalfWidth = 12.5, kNasalRoofHalfWidth = 5, kNasalBoneThickness = 2.5;
constexpr double kSeptumHalfThickness = 1.0, kSeptumBack = 24, kSeptumFront = 60, kSeptumTop = 25;
const Vector3d kNostrilInner = lps(7, 66, -18), kNostrilOuter = lps(7, 90, -24);
constexpr double kNostrilRadius = 3.5;
// Maxillary sinus (left): 25 x 35 x 29 mm (width, antero-posterior, height), walls >= 2.5 mm.
const Vector3d kSinusCentre = lps(27.5, 40, -13);
const Vector3d kSinusSemiAxes{12.5, 17.5, 14.5};
// External acoustic meatus (left): its top line is at z = 0 (porion on Frankfort).
const Vector3d kEarCanalInner = lps(38, -20, -4), kEarCanalOuter = lps(90, -20, -4);
constexpr double kEarCanalRadius = 4;
// Temporomandibular joint space around the condyle (see phantom_mandible.cpp).
const Vector3d kJointCentre = lps(50, -8, -4.5);
const Vector3d kJointSemiAxes{12, 7, 6.5};

bool in_orbit(const Vector3d& p) {
  double a = anterior(p), depth = anterior(kOrbitOpening) - kOrbitRimDepth - anterior(kOrbitApex);
  double t = std::max(0.0, (anterior(kOrbitOpening) - kOrbitRimDepth - a) / depth);
  if (t > 1) return false;
  Vector3d centre = kOrbitOpening + t * (kOrbitApex - kOrbitOpening);
  double scale = 1 - 0.9 * std::pow(t, 1.2);
  double u = (p.x() - centre.x()) / (kOrbitHalfWidth * scale), v = (p.z() - centre.z()) / (kOrbitHalfHeight * scale);
  return u * u + v * v < 1;
}

}  // namespace

void add_cavity_parts(const PhantomDesign& d, PartList& parts) {
  const TissueMask bone = mask_of(Tissue::kBone);
  parts.push_back(bilateral("orbit", Box::spanning(lps(10, 100, -1), lps(54, anterior(kOrbitApex), 36)), in_orbit,
                            Tissue::kSoftTissue, Material::kFat, bone));
  parts.push_back(bilateral(
      "eye", Box::around(kEyeCentre, Vector3d::Constant(kEyeRadius)),
      [](const Vector3d& p) { return (p - kEyeCentre).norm() < kEyeRadius; }, Tissue::kSoftTissue, Material::kVitreous,
      mask_of(Tissue::kSoftTissue)));
  parts.push_back(with_maxilla(
      d, {"nasal cavity",
          Box::spanning(lps(-kNasalFloorHalfWidth, kNasalBack, -30), lps(kNasalFloorHalfWidth, 85, kNasalRoof)),
          [d](const Vector3d& p) {
            double a = anterior(p), z = p.z();
            if (a < kNasalBack || z > kNasalRoof || z < d.palatal_z(a) + 2) return false;
            double half_width = lerp(kNasalFloorHalfWidth, kNasalRoofHalfWidth, smoothstep(-22, kNasalRoof, z));
            if (std::abs(p.x()) > half_width) return false;
            double front = z < 6 ? kNasalApertureFront : nasal_bone_front(d, p.x(), z) - kNasalBoneThickness;
            return a < front;
          },
          Tissue::kAir, Material::kAir, mask_of(Tissue::kBone, Tissue::kSoftTissue)}));
  parts.push_back(with_maxilla(d, {"nasal septum",
                                   Box::spanning(lps(-kSeptumHalfThickness, kSeptumBack, -30),
                                                 lps(kSeptumHalfThickness, kSeptumFront, kSeptumTop)),
                                   [d](const Vector3d& p) {
                                     double a = anterior(p);
                                     return std::abs(p.x()) < kSeptumHalfThickness && a > kSeptumBack &&
                                            a < kSeptumFront && p.z() < kSeptumTop && p.z() > d.palatal_z(a);
                                   },
                                   Tissue::kBone, Material::kBone, mask_of(Tissue::kAir)}));
  parts.push_back(bilateral(
      "nostril", capsule_box(kNostrilInner, kNostrilOuter, kNostrilRadius),
      [](const Vector3d& p) { return segment_distance(p, kNostrilInner, kNostrilOuter) < kNostrilRadius; },
      Tissue::kAir, Material::kAir, mask_of(Tissue::kSoftTissue)));
  parts.push_back(with_maxilla(d, bilateral(
                                      "maxillary sinus", ellipsoid_box(kSinusCentre, kSinusSemiAxes),
                                      [](const Vector3d& p) { return in_ellipsoid(p, kSinusCentre, kSinusSemiAxes); },
                                      Tissue::kSinusAir, Material::kAir, bone)));
  parts.push_back(bilateral(
      "ear canal", capsule_box(kEarCanalInner, kEarCanalOuter, kEarCanalRadius),
      [](const Vector3d& p) { return segment_distance(p, kEarCanalInner, kEarCanalOuter) < kEarCanalRadius; },
      Tissue::kAir, Material::kAir, mask_of(Tissue::kBone, Tissue::kSoftTissue)));
  parts.push_back(bilateral(
      "temporomandibular joint space", ellipsoid_box(kJointCentre, kJointSemiAxes),
      [](const Vector3d& p) { return in_ellipsoid(p, kJointCentre, kJointSemiAxes); }, Tissue::kSoftTissue,
      Material::kSoft, bone));
}

}  // namespace maxillo::sample
