// Soft tissue envelope: scalp, face (skin height field) and neck.
#include <cmath>
#include <limits>
#include <memory>
#include <span>

#include "sample/phantom_parts.h"
#include "sample/phantom_skin.h"

namespace maxillo::sample {
namespace {

using Knot = std::pair<double, double>;

double piecewise_linear(double z, std::span<const Knot> knots) {  // knots: z ascending
  if (z <= knots.front().first) return knots.front().second;
  for (size_t i = 1; i < knots.size(); ++i)
    if (z <= knots[i].first)
      return lerp(knots[i - 1].second, knots[i].second,
                  (z - knots[i - 1].first) / (knots[i].first - knots[i - 1].first));
  return knots.back().second;
}

// Featureless face front at the midline (mm): what the cheeks fall off from.
constexpr Knot kFaceBase[] = {{-105, 45}, {-95, 62}, {-80, 72}, {-60, 78}, {-45, 80},
                              {-20, 80},  {0, 79},   {30, 75},  {60, 74}};
// Lateral width (mm) over which the midline features (nose, lips, chin) fade.
constexpr Knot kFeatureWidth[] = {{-100, 30}, {-80, 22}, {-60, 26}, {-40, 26}, {-26, 18},
                                  {-15, 13},  {10, 12},  {30, 18},  {45, 40}};
constexpr Knot kFaceHalfWidth[] = {{-100, 44}, {-80, 52}, {-40, 66}, {0, 72}};
constexpr double kCheekDepth = 60;  // the face front falls back by this much at the half-width

// Scalp: the cranial ellipsoid grown by ~5 mm.
const Vector3d kScalpCentre = lps(0, -21, 40);
const Vector3d kScalpSemiAxes{75, 97, 90};
constexpr double kScalpBottom = -40;
// Neck: vertical elliptic cylinder below the skull base.
constexpr double kNeckCentreA = -15, kNeckHalfWidth = 58, kNeckHalfDepth = 55, kNeckTop = -20;
constexpr double kFaceBack = -20, kFaceTop = 50;

// Lower lip and chin follow the mandible, the upper lip the maxilla.
double upper_lip_weight(double z) { return smoothstep(-22, -30, z) * smoothstep(-56, -49, z); }
double lower_lip_weight(double z) { return smoothstep(-48, -55, z); }

}  // namespace

SkinProfile::SkinProfile(const PhantomDesign& design) : design_(design) {
  const double n_a = anterior(design.N) + kNasionSoftThickness;
  const double pog_a = anterior(design.Pog) + kPogonionSoftThickness;
  knots_ = {{{-103, 40},
             {-98, 60},
             {-90, 73},
             {design.Pog.z(), pog_a},         // soft pogonion (max)
             {-68, 76},                       // soft B, labiomental fold (min)
             {kLabraleInferiusHeight, 85},    // labrale inferius (max)
             {kStomionHeight, 83.5},          // stomion (min)
             {kLabraleSuperiusHeight, 86.5},  // labrale superius (max)
             {kSubnasaleHeight, 82},          // subnasale (min)
             {-22, 93},
             {kPronasaleHeight, 99},  // pronasale (max)
             {-2, 93},
             {12, 85},
             {design.N.z(), n_a},  // soft nasion (min)
             {45, 77},
             {60, 74}}};
  // Fritsch-Carlson monotone slopes: zero at every local extremum of the knots.
  const size_t n = knots_.size();
  std::array<double, 16> secant{};
  for (size_t i = 0; i + 1 < n; ++i)
    secant[i] = (knots_[i + 1].second - knots_[i].second) / (knots_[i + 1].first - knots_[i].first);
  slopes_[0] = secant[0];
  slopes_[n - 1] = secant[n - 2];
  for (size_t i = 1; i + 1 < n; ++i) {
    double h0 = knots_[i].first - knots_[i - 1].first, h1 = knots_[i + 1].first - knots_[i].first;
    if (secant[i - 1] * secant[i] <= 0) {
      slopes_[i] = 0;
    } else {
      double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
      slopes_[i] = (w1 + w2) / (w1 / secant[i - 1] + w2 / secant[i]);
    }
  }
}

double SkinProfile::reference_midline(double z) const {
  if (z <= knots_.front().first) return knots_.front().second;
  if (z >= knots_.back().first) return knots_.back().second;
  size_t i = 1;
  while (z > knots_[i].first) ++i;
  const auto& [z0, a0] = knots_[i - 1];
  const auto& [z1, a1] = knots_[i];
  double h = z1 - z0, t = (z - z0) / h;
  double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  return h00 * a0 + h10 * h * slopes_[i - 1] + h01 * a1 + h11 * h * slopes_[i];
}

double SkinProfile::midline(double z) const {
  return reference_midline(z) + design_.maxilla_shift * upper_lip_weight(z) +
         design_.mandible_shift * lower_lip_weight(z);
}

double SkinProfile::half_width(double z) { return piecewise_linear(z, kFaceHalfWidth); }

double SkinProfile::surface(double x, double z) const {
  double w = half_width(z);
  double r = x / w;
  if (r * r >= 1) return -std::numeric_limits<double>::infinity();
  double base = piecewise_linear(z, kFaceBase);
  double feature_width = piecewise_linear(z, kFeatureWidth);
  double cheek = kCheekDepth * (1 - std::sqrt(1 - r * r));
  return base - cheek + (midline(z) - base) * std::exp(-(x * x) / (feature_width * feature_width));
}

void add_soft_tissue_parts(const PhantomDesign& design, PartList& parts) {
  parts.push_back(
      {"scalp", ellipsoid_box(kScalpCentre, kScalpSemiAxes),
       [](const Vector3d& p) { return p.z() > kScalpBottom && in_ellipsoid(p, kScalpCentre, kScalpSemiAxes); },
       Tissue::kSoftTissue, Material::kSoft});
  auto skin = std::make_shared<SkinProfile>(design);
  parts.push_back({"face", Box::spanning(lps(-75, 110, -110), lps(75, kFaceBack, kFaceTop)),
                   [skin](const Vector3d& p) {
                     double a = anterior(p);
                     double submental = -99 - 0.1 * std::max(0.0, 70 - a);
                     return a > kFaceBack && p.z() > submental && a < skin->surface(p.x(), p.z());
                   },
                   Tissue::kSoftTissue, Material::kSoft});
  parts.push_back({"neck",
                   Box::spanning(lps(-kNeckHalfWidth, kNeckCentreA + kNeckHalfDepth, -1000),
                                 lps(kNeckHalfWidth, kNeckCentreA - kNeckHalfDepth, kNeckTop)),
                   [](const Vector3d& p) {
                     double u = p.x() / kNeckHalfWidth, v = (anterior(p) - kNeckCentreA) / kNeckHalfDepth;
                     return p.z() < kNeckTop && u * u + v * v < 1;
                   },
                   Tissue::kSoftTissue, Material::kSoft});
}

}  // namespace maxillo::sample
