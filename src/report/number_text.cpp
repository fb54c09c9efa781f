#include "report/number_text.h"

#include <cmath>
#include <cstdio>

namespace maxillo::report {

std::string fixed(double value, int decimals) {
  char text[48];
  const bool rounds_to_zero = std::abs(value) < 0.5 * std::pow(10.0, -decimals);
  std::snprintf(text, sizeof text, "%.*f", decimals, rounds_to_zero ? 0.0 : value);
  return text;
}

}  // namespace maxillo::report
