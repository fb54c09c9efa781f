#pragma once
// The skin of the face as a height field: for a height z and lateral offset x, the anterior
// coordinate a_skin(x, z) of the skin surface (mm). In the mid-sagittal plane it is the designed
// soft-tissue profile, a monotone cubic through the soft landmarks (so each profile landmark is
// an exact local extremum); laterally it falls off to the cheeks.
#include <array>
#include <utility>

#include "sample/phantom_design.h"

namespace maxillo::sample {

// Heights (z, mm) of the mid-sagittal soft landmarks; soft nasion and soft pogonion sit at the
// heights of N and Pog.
inline constexpr double kPronasaleHeight = -15;
inline constexpr double kSubnasaleHeight = -26;
inline constexpr double kLabraleSuperiusHeight = -43;
inline constexpr double kStomionHeight = -50;
inline constexpr double kLabraleInferiusHeight = -57;
// Soft-tissue thickness (mm, horizontal) designed at nasion and pogonion.
inline constexpr double kNasionSoftThickness = 6;
inline constexpr double kPogonionSoftThickness = 11;

class SkinProfile {
 public:
  explicit SkinProfile(const PhantomDesign& design);
  // Mid-sagittal skin a(z), including the lip/chin displacement of the spec.
  double midline(double z) const;
  // Skin a at lateral offset x (either side); -inf outside the face's width.
  double surface(double x, double z) const;
  // Face half-width at height z.
  static double half_width(double z);

 private:
  double reference_midline(double z) const;
  PhantomDesign design_;
  std::array<std::pair<double, double>, 16> knots_;  // (z ascending, a)
  std::array<double, 16> slopes_;
};

}  // namespace maxillo::sample
