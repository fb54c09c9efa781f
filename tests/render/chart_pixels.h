#pragma once
// Where a colour appears in a rendered chart: for tests that check what was drawn where.
#include <algorithm>
#include <cstdlib>

#include "render/chart.h"

namespace maxillo::render::test {

inline bool near_colour(const std::uint8_t* px, const ColourRGB& colour, int tolerance = 30) {
  const double ref[3] = {colour.r * 255, colour.g * 255, colour.b * 255};
  for (int c = 0; c < 3; ++c)
    if (std::abs(px[c] - ref[c]) > tolerance) return false;
  return true;
}

// The pixels of one colour: how many, their bounding box (rows counted from the image's top) and mean row.
struct ColourPixels {
  long count = 0;
  int min_x = 1 << 30, max_x = -1, min_y = 1 << 30, max_y = -1;
  double mean_y = 0;
  int width() const { return max_x - min_x + 1; }
  int height() const { return max_y - min_y + 1; }
};

inline ColourPixels find_colour(const RgbImage& image, const ColourRGB& colour, int tolerance = 30) {
  ColourPixels n;
  double rows = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (near_colour(image.at(x, y), colour, tolerance)) {
        ++n.count;
        rows += y;
        n.min_x = std::min(n.min_x, x), n.max_x = std::max(n.max_x, x);
        n.min_y = std::min(n.min_y, y), n.max_y = std::max(n.max_y, y);
      }
  if (n.count > 0) n.mean_y = rows / double(n.count);
  return n;
}

}  // namespace maxillo::render::test
