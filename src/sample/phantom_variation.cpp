#include "sample/phantom_variation.h"

#include <Eigen/Geometry>
#include <cstdio>
#include <random>

#include "core/angles.h"
#include "core/sha256.h"

namespace maxillo {
namespace {

// Uniform draws in [lo, hi) from the ID's generator. The mapping from the 64-bit output is
// written here (std::uniform_real_distribution's is left to the library).
class Draws {
 public:
  explicit Draws(std::string_view patient_id) : random_(seed_of(patient_id)) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(random_() >> 11) * 0x1.0p-53; }
  bool coin() { return random_() >> 63; }
  uint32_t seed() { return uint32_t(random_() >> 32); }

 private:
  static uint64_t seed_of(std::string_view patient_id) {
    const std::string digest = sha256_hex(std::string("maxillo phantom patient: ") + std::string(patient_id));
    return std::stoull(digest.substr(0, 16), nullptr, 16);
  }
  std::mt19937_64 random_;
};

// A chin deviation up to this far to either side.
constexpr double kChinDeviationMm = 3;

PhantomPlacement draw_placement(Draws& draws) {
  PhantomPlacement placement;
  placement.scale = draws.uniform(0.92, 1.08);
  const double yaw = draws.uniform(-15, 15), pitch = draws.uniform(-15, 15), roll = draws.uniform(-15, 15);
  placement.rotation = (Eigen::AngleAxisd(yaw * kDeg, Eigen::Vector3d::UnitZ()) *
                        Eigen::AngleAxisd(pitch * kDeg, Eigen::Vector3d::UnitX()) *
                        Eigen::AngleAxisd(roll * kDeg, Eigen::Vector3d::UnitY()))
                           .toRotationMatrix();
  for (int axis = 0; axis < 3; ++axis) placement.shift[axis] = draws.uniform(-15, 15);
  return placement;
}

ConeBeamFlavour draw_cone_beam(Draws& draws) {
  ConeBeamFlavour flavour;
  flavour.grey_per_hu = draws.uniform(0.5, 1.5);
  flavour.grey_of_air = draws.uniform(-1000, 500);
  flavour.cupping = draws.uniform(0.05, 0.2);
  flavour.streak_hu = draws.uniform(200, 500);
  flavour.field_radius_mm = draws.uniform(75, 90);
  flavour.field_top_mm = draws.uniform(25, 60);
  flavour.field_bottom_mm = draws.uniform(-105, -85);
  flavour.field_centre_mm = {draws.uniform(-5, 5), draws.uniform(-40, -20)};
  flavour.padding_grey = flavour.grey_of_air - (draws.coin() ? 200 : 0);
  return flavour;
}

}  // namespace

PhantomSpec varied_phantom_spec(std::string_view patient_id, ScannerKind scanner, double spacing_mm) {
  Draws draws(patient_id);
  PhantomSpec spec;
  spec.spacing_mm = spacing_mm;
  spec.placement = draw_placement(draws);
  spec.maxillary_advancement_mm = draws.uniform(-3, 3);
  spec.mandibular_protrusion_mm = draws.uniform(-6, 6);
  spec.noise_seed = draws.seed();
  if (scanner == ScannerKind::kConeBeam) {
    spec.noise_sigma_hu = draws.uniform(20, 50);
    spec.cone_beam = draw_cone_beam(draws);
  } else {
    spec.noise_sigma_hu = draws.uniform(5, 30);
  }
  // Drawn last, so that the draws above (and the patients they made before) stay the same.
  spec.mandibular_deviation_mm = draws.uniform(-kChinDeviationMm, kChinDeviationMm);
  return spec;
}

std::string describe_variation(const PhantomSpec& spec) {
  char text[320];
  std::snprintf(text, sizeof text,
                "scale %.3f, maxilla %+.1f mm, mandible %+.1f mm, chin %+.1f mm to the left, turned %.1f deg, "
                "shifted (%.1f, %.1f, %.1f) mm, noise %.0f HU",
                spec.placement.scale, spec.maxillary_advancement_mm, spec.mandibular_protrusion_mm,
                spec.mandibular_deviation_mm, Eigen::AngleAxisd(spec.placement.rotation).angle() / kDeg,
                spec.placement.shift.x(), spec.placement.shift.y(), spec.placement.shift.z(), spec.noise_sigma_hu);
  std::string description = text;
  if (const auto& cb = spec.cone_beam) {
    std::snprintf(text, sizeof text,
                  "; cone-beam: grey = %.0f + %.2f (HU + 1000), cupping %.0f %%, field r %.0f mm, z %.0f to %.0f mm",
                  cb->grey_of_air, cb->grey_per_hu, 100 * cb->cupping, cb->field_radius_mm, cb->field_bottom_mm,
                  cb->field_top_mm);
    description += text;
  }
  return description;
}

}  // namespace maxillo
