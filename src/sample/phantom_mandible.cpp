// Mandible: the body (a U band along the lower arch), the mental protuberance (chin: Pog, Gn,
// Me by construction), both rami (plates from the gonial angle up to the coronoid process and
// the condylar neck, Go as a polygon vertex) and the condyles; articulare is read off the parts
// (phantom_landmarks.cpp).
#include <array>

#include "sample/phantom_parts.h"
#include "sample/phantom_mandible.h"

namespace maxillo::sample {
namespace {

// Body: a band around the lower dental arch. In superelliptic coordinates of the arch
// (rho = 1 on the arch), laterally from rho 0.8 to 1.18 (~11 mm); at the midline its front
// follows the designed symphysis profile and it is 13 mm thick. Behind the molars a straight
// segment joins the rami. Height: from the lower border up to the alveolar crest.
constexpr double kBodyInnerRho = 0.8, kBodyOuterRho = 1.18, kSymphysisThickness = 13;
const std::array<Vector2d, 4> kPosteriorBody = {{{20.5, 34}, {32, 34}, {50.5, 2}, {43.5, 2}}};  // (x, a)
constexpr double kCrestBelowOcclusal = 8.5;
constexpr double kLowerBorderSlope = 0.475;  // mandibular plane rises 0.475 mm per mm posteriorly
constexpr double kBorderAboveMenton = 4;     // body's lower border at the chin, above Me
// Ramus plates: mid-plane x goes from 47 mm (angle) to 50 mm (condyle); 7 mm thick.
constexpr double kRamusXAtAngle = 47, kRamusXAtCondyle = 50, kRamusHalfThickness = 3.5;
const Vector3d kCondyleCentre = lps(50, -8, -4.5);
const Vector3d kCondyleSemiAxes{9, 4.5, 4.5};

double body_front(const PhantomDesign& d, double z) {
  if (z >= d.Pog.z()) return d.lower_alveolar_front(z);
  return anterior(d.Pog) - 3 - (d.Pog.z() - z) * 0.3;  // behind the chin below Pog
}

double lower_border(const PhantomDesign& d, double a) {
  return d.Me.z() + kBorderAboveMenton + std::max(0.0, anterior(d.Me) - a) * kLowerBorderSlope;
}

bool in_body_height(const PhantomDesign& d, double a, double z) {
  return z > lower_border(d, a) && z < d.occlusal_z(a) - kCrestBelowOcclusal;
}

bool in_body(const PhantomDesign& d, const Vector3d& p) {
  const ArchShape& arch = kLowerArch;
  double a = anterior(p), z = p.z();
  if (a < arch.centre() || !in_body_height(d, a, z)) return false;
  double u = p.x() / arch.half_width, v = (a - arch.centre()) / arch.depth;
  double rho = std::pow(std::pow(std::abs(u), arch.exponent) + std::pow(std::abs(v), arch.exponent), 1 / arch.exponent);
  double angle = std::atan2(std::abs(u), v);
  double lateral = smoothstep(0.25, 0.7, angle);
  double front_outer = (body_front(d, z) - arch.centre()) / arch.depth;
  double outer = lerp(front_outer, kBodyOuterRho, lateral);
  double inner = lerp(front_outer - kSymphysisThickness / arch.depth, kBodyInnerRho, lateral);
  return rho > inner && rho < outer;
}

bool in_posterior_body(const PhantomDesign& d, const Vector3d& p) {
  double a = anterior(p);
  return in_body_height(d, a, p.z()) && in_polygon(Vector2d(p.x(), a), kPosteriorBody);
}

}  // namespace

double ramus_mid_plane_x(double z) { return lerp(kRamusXAtAngle, kRamusXAtCondyle, smoothstep(-56, -5, z)); }

std::array<Vector2d, 11> ramus_outline(const PhantomDesign& d) {
  // (a, z), counter-clockwise from the gonial angle: posterior border, condylar neck, sigmoid
  // notch, coronoid process, anterior border, retromolar region, lower border back to Go.
  return {{{-7, -56},  // Go
           {-11, -32},
           {-12.5, -11.5},
           {-11.5, -5},
           {-4.5, -5},
           {1, -17},
           {11, -4},  // coronoid tip
           {17, -20},
           {24, -42},
           {34, -54},
           {30, lower_border(d, 30)}}};
}

Vector3d gonion(const PhantomDesign& d, Side side) {
  Vector2d go = ramus_outline(d)[0];
  double sign = side == Side::kLeft ? 1 : -1;
  return lps(sign * ramus_mid_plane_x(go.y()), go.x(), go.y());
}

void add_mandible_parts(const PhantomDesign& d, PartList& parts) {
  const TissueMask soft = mask_of(Tissue::kAir, Tissue::kSoftTissue);
  const Vector3d chin_centre = d.Pog - lps(0, kChinDepth, 0);  // behind Pog
  const Vector3d chin_semi{kChinHalfWidth, kChinDepth, kChinHeight};
  parts.push_back(
      with_mandible(d, {"mental protuberance", ellipsoid_box(chin_centre, chin_semi),
                        [chin_centre, chin_semi](const Vector3d& p) { return in_ellipsoid(p, chin_centre, chin_semi); },
                        Tissue::kMandible, Material::kBone, soft}));
  parts.push_back(
      with_mandible(d, {"mandibular body", Box::spanning(lps(-35, 20, d.Me.z()), lps(35, 80, -40)),
                        [d](const Vector3d& p) { return in_body(d, p); }, Tissue::kMandible, Material::kBone, soft}));
  parts.push_back(with_mandible(
      d, bilateral(
             "mandibular body behind the molars", Box::spanning(lps(20, 0, -90), lps(51, 36, -40)),
             [d](const Vector3d& p) { return in_posterior_body(d, p); }, Tissue::kMandible, Material::kBone, soft)));
  const auto outline = ramus_outline(d);
  parts.push_back(bilateral(
      "ramus", Box::spanning(lps(kRamusXAtAngle - 5, -15, -80), lps(kRamusXAtCondyle + 5, 36, 0)),
      [outline](const Vector3d& p) {
        return std::abs(p.x() - ramus_mid_plane_x(p.z())) < kRamusHalfThickness &&
               in_polygon(Vector2d(anterior(p), p.z()), outline);
      },
      Tissue::kMandible, Material::kBone, soft));
  parts.push_back(bilateral(
      "condyle", ellipsoid_box(kCondyleCentre, kCondyleSemiAxes),
      [](const Vector3d& p) { return in_ellipsoid(p, kCondyleCentre, kCondyleSemiAxes); }, Tissue::kMandible,
      Material::kBone, soft));
}

}  // namespace maxillo::sample
