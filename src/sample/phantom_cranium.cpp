// Cranium: vault and skull base (bone), brain, sella turcica, temporal bones.
#include "sample/phantom_parts.h"

namespace maxillo::sample {
namespace {

// Outer table of the skull: an ellipsoid 140 x 184 x 170 mm; the inner table 7 mm inside.
const Vector3d kCraniumCentre = lps(0, -21, 40);
const Vector3d kCraniumOuter{70, 92, 85};
const Vector3d kCraniumInner{63, 85, 78};
// Cranial fossae floors (z of the brain's underside, mm) and skull base thickness.
constexpr double kAnteriorFossaFloor = 40;    // over the orbits, anterior to a = 28
constexpr double kMiddleFossaFloor = 2;       // temporal lobes, lateral to |x| = 18
constexpr double kSphenoidTop = 24;           // central skull base around the sella
constexpr double kPosteriorFossaFloor = -18;  // cerebellum, posterior to a = -20
constexpr double kBaseThickness = 9;
constexpr double kSphenoidBodyThickness = 30;  // down to the nasopharynx roof
// Sella turcica: a spherical pit in the sphenoid top, centred on S.
constexpr double kSellaRadius = 6;
// Petrous and mastoid part of each temporal bone (solid), around the ear canal.
const Vector3d kTemporalCentre = lps(47, -24, -5);
const Vector3d kTemporalSemiAxes{15, 10, 10};

struct BaseShape {
  double floor;      // z of the brain's underside
  double thickness;  // bone below it
};

BaseShape skull_base(double x, double a) {
  double anterior_zone = smoothstep(24, 32, a);
  double posterior_zone = smoothstep(-14, -20, a);
  double central = smoothstep(18, 13, std::abs(x)) * (1 - anterior_zone) * (1 - posterior_zone);
  double middle = lerp(kMiddleFossaFloor, kSphenoidTop, central);
  double floor = lerp(lerp(middle, kAnteriorFossaFloor, anterior_zone), kPosteriorFossaFloor, posterior_zone);
  double thickness = lerp(kBaseThickness, kSphenoidBodyThickness, central);
  return {floor, thickness};
}

}  // namespace

void add_cranium_parts(const PhantomDesign& design, PartList& parts) {
  parts.push_back({"cranial vault and base", ellipsoid_box(kCraniumCentre, kCraniumOuter),
                   [](const Vector3d& p) {
                     BaseShape base = skull_base(p.x(), anterior(p));
                     return p.z() > base.floor - base.thickness && in_ellipsoid(p, kCraniumCentre, kCraniumOuter);
                   },
                   Tissue::kBone, Material::kBone});
  parts.push_back({"brain", ellipsoid_box(kCraniumCentre, kCraniumInner),
                   [](const Vector3d& p) {
                     return p.z() > skull_base(p.x(), anterior(p)).floor &&
                            in_ellipsoid(p, kCraniumCentre, kCraniumInner);
                   },
                   Tissue::kSoftTissue, Material::kBrain});
  const Vector3d sella = design.S;
  parts.push_back({"pituitary fossa (sella turcica)", Box::around(sella, Vector3d::Constant(kSellaRadius)),
                   [sella](const Vector3d& p) { return (p - sella).norm() < kSellaRadius; }, Tissue::kSoftTissue,
                   Material::kSoft, mask_of(Tissue::kBone)});
  parts.push_back(bilateral(
      "temporal bone", ellipsoid_box(kTemporalCentre, kTemporalSemiAxes),
      [](const Vector3d& p) { return in_ellipsoid(p, kTemporalCentre, kTemporalSemiAxes); }, Tissue::kBone,
      Material::kBone));
}

}  // namespace maxillo::sample
