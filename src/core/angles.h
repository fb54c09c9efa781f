#pragma once
// Degrees and radians: plans, reports and cephalometry speak degrees, the trigonometry radians.
#include <numbers>

namespace maxillo {

// One degree in radians: an angle in degrees times kDeg is in radians.
inline constexpr double kDeg = std::numbers::pi / 180;

constexpr double radians(double degrees) { return degrees * kDeg; }
constexpr double degrees(double radians) { return radians / kDeg; }

}  // namespace maxillo
