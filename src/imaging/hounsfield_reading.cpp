#include "imaging/hounsfield_reading.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/parallel_slabs.h"
#include "imaging/cupping_correction.h"

namespace maxillo {

std::string GreyReading::describe() const {
  std::string text = grey.describe();
  if (cupping_depth > 0) {
    char cupping[96];
    std::snprintf(cupping, sizeof cupping, ", after a cone-beam cupping of %.0f %% was undone", 100 * cupping_depth);
    text += cupping;
  }
  return text;
}

GreyReading read_grey_values(const Volume& scan, Volume* uncupped) {
  GreyReading reading;
  reading.grey = estimate_grey_calibration(scan);
  // A cone-beam scan loses more towards its axis: undone first, or the thresholds that hold at
  // the rim do not hold in the middle. A CT is read as it is.
  if (reading.grey.is_hounsfield()) return reading;
  const RadialCupping cupping = estimate_cupping(scan, reading.grey);
  if (!cupping.significant()) return reading;
  Volume undone = without_cupping(scan, reading.grey, cupping);
  reading.cupping_depth = cupping.depth();
  reading.grey = estimate_grey_calibration(undone);
  if (uncupped) *uncupped = std::move(undone);
  return reading;
}

std::optional<Volume> in_hounsfield_units(const Volume& scan, GreyReading* reading_out) {
  Volume uncupped;
  const GreyReading reading = read_grey_values(scan, &uncupped);
  if (reading_out) *reading_out = reading;
  if (reading.hounsfield_as_stored()) return std::nullopt;
  Volume hu = uncupped.hu.empty() ? scan : std::move(uncupped);
  const auto& grey = reading.grey;
  for_each_slab(0, hu.geometry.size.z(), [&](int first, int last) {
    const auto begin = size_t(hu.geometry.index(0, 0, first)), end = size_t(hu.geometry.index(0, 0, last));
    for (size_t i = begin; i < end; ++i) {
      int16_t& v = hu.hu[i];
      v = grey.padding && v == *grey.padding ? int16_t(-1000)
                                             : int16_t(std::lround(std::clamp(grey.to_hu(v), -1024.0, 30000.0)));
    }
  });
  return hu;
}

Volume as_hounsfield_units(Volume scan, GreyReading* reading) {
  if (auto converted = in_hounsfield_units(scan, reading)) return std::move(*converted);
  return scan;
}

}  // namespace maxillo
