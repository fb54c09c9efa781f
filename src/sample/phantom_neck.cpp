// Neck contents: the pharyngeal airway (from the choanae down through the field of view) and a
// cervical spine (atlas ring, C2 with the dens, C3-C7 bodies, arches, spinous processes, canal),
// with the foramen magnum opened in the occipital bone.
#include <array>

#include "sample/phantom_parts.h"

namespace maxillo::sample {
namespace {

// Airway: elliptic tube (half width x, half depth a) along a polyline in the mid-sagittal plane.
constexpr double kAirwayHalfWidth = 11, kAirwayHalfDepth = 6;
const std::array<Vector2d, 4> kAirwayPath = {{{15, -16}, {11, -40}, {9, -80}, {8, -200}}};  // (a, z)
// Spine: vertebral bodies centred at a = -9 (radius 8 mm), canal at a = -24 (radius 7.5 mm),
// arch ring radius 12 mm around the canal, spinous processes back to a = -50.
constexpr double kBodyCentreA = -9, kBodyRadius = 8, kCanalCentreA = -24, kCanalRadius = 7.5;
constexpr double kArchRadius = 12, kSpinousTipA = -50, kSpinousRadius = 3;
struct Level {
  double bottom, top;
};
// C2 (with the dens up to -30) to C7; discs (soft tissue) between the bodies.
constexpr std::array<Level, 6> kBodies = {
    {{-62, -40}, {-78, -65}, {-94, -81}, {-110, -97}, {-126, -113}, {-142, -129}}};
constexpr double kDensTop = -30, kDensRadius = 5;
constexpr Level kAtlas{-42, -34};  // C1: a ring around the dens and the canal (no body)
constexpr double kAtlasCentreA = -18, kAtlasInnerRadius = 14, kAtlasOuterRadius = 18;
constexpr double kForamenMagnumBottom = -34, kForamenMagnumTop = -10;

bool in_airway(const Vector3d& p) {
  double a = anterior(p), z = p.z();
  for (size_t i = 0; i + 1 < kAirwayPath.size(); ++i) {
    const Vector2d &upper = kAirwayPath[i], &lower = kAirwayPath[i + 1];
    if (z > upper.y() || z < lower.y()) continue;
    double centre = lerp(upper.x(), lower.x(), (z - upper.y()) / (lower.y() - upper.y()));
    double u = p.x() / kAirwayHalfWidth, v = (a - centre) / kAirwayHalfDepth;
    return u * u + v * v < 1;
  }
  return false;
}

double radial(const Vector3d& p, double centre_a) { return std::hypot(p.x(), anterior(p) - centre_a); }

bool in_vertebra(const Vector3d& p) {
  const double z = p.z();
  for (const Level& level : kBodies)
    if (z > level.bottom && z < level.top) {
      if (radial(p, kBodyCentreA) < kBodyRadius) return true;
      if (radial(p, kCanalCentreA) < kArchRadius) return true;  // arch (canal carved later)
      if (std::abs(z - (level.top - 4)) < kSpinousRadius && std::abs(p.x()) < kSpinousRadius &&
          anterior(p) < kCanalCentreA && anterior(p) > kSpinousTipA)
        return true;
    }
  if (z > kBodies[0].top && z < kDensTop && radial(p, kBodyCentreA) < kDensRadius) return true;
  if (z > kAtlas.bottom && z < kAtlas.top) {
    double r = radial(p, kAtlasCentreA);
    return r > kAtlasInnerRadius && r < kAtlasOuterRadius;
  }
  return false;
}

}  // namespace

void add_neck_parts(const PhantomDesign&, PartList& parts) {
  const TissueMask soft = mask_of(Tissue::kSoftTissue);
  parts.push_back(
      {"foramen magnum",
       Box::spanning(lps(-kCanalRadius, kCanalCentreA - kCanalRadius, kForamenMagnumBottom),
                     lps(kCanalRadius, kCanalCentreA + kCanalRadius, kForamenMagnumTop)),
       [](const Vector3d& p) { return p.z() < kForamenMagnumTop && radial(p, kCanalCentreA) < kCanalRadius; },
       Tissue::kSoftTissue, Material::kSoft, mask_of(Tissue::kBone)});
  parts.push_back({"cervical spine", Box::spanning(lps(-25, 10, -200), lps(25, kSpinousTipA, kDensTop)), in_vertebra,
                   Tissue::kBone, Material::kBone, soft});
  parts.push_back({"spinal canal",
                   Box::spanning(lps(-kCanalRadius, kCanalCentreA - kCanalRadius, -200),
                                 lps(kCanalRadius, kCanalCentreA + kCanalRadius, kForamenMagnumBottom)),
                   [](const Vector3d& p) { return radial(p, kCanalCentreA) < kCanalRadius; }, Tissue::kSoftTissue,
                   Material::kSoft, mask_of(Tissue::kBone)});
  parts.push_back({"pharyngeal airway", Box::spanning(lps(-kAirwayHalfWidth, 25, -200), lps(kAirwayHalfWidth, 0, -16)),
                   in_airway, Tissue::kAir, Material::kAir, soft});
}

}  // namespace maxillo::sample
