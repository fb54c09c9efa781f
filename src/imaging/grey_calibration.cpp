#include "imaging/grey_calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace maxillo {
namespace {

constexpr int kBins = 1024;

struct Histogram {
  int low = 0;
  double width = 1;
  std::vector<double> counts;
  double centre(size_t bin) const { return low + (double(bin) + 0.5) * width; }
};

// A scanner fills what it did not reconstruct (a cone-beam scan's corners outside its cylinder,
// a CT's outside its circle) with one value, below air's or air's own. Tissue and air are noisy,
// so that value is a spike: far more frequent than both values next to it. Below air it is the
// lowest value and must be left out of the histogram, or it would be taken for air's mode.
bool is_spike(const std::vector<int64_t>& full, size_t value, int64_t total) {
  const int64_t below = value > 0 ? full[value - 1] : 0, above = value + 1 < full.size() ? full[value + 1] : 0;
  return full[value] > total / 50 && full[value] > 20 * std::max(below, above);
}

std::optional<int> lowest_value_spike(const std::vector<int64_t>& full, int64_t total) {
  size_t lowest = 0;
  while (lowest + 1 < full.size() && full[lowest] == 0) ++lowest;
  if (is_spike(full, lowest, total)) return int(lowest) - 32768;
  return std::nullopt;
}

std::optional<int> most_frequent_value_spike(const std::vector<int64_t>& full, int64_t total) {
  const size_t most = size_t(std::max_element(full.begin(), full.end()) - full.begin());
  if (is_spike(full, most, total)) return int(most) - 32768;
  return std::nullopt;
}

// How far the run of `value` reaches into row j of slice k from the row's start (`from_start`)
// or its end; -1 when the whole row is that value.
int run_from_side(const Volume& volume, int value, int j, int k, bool from_start) {
  const int n = volume.geometry.size.x();
  for (int step = 0; step < n; ++step)
    if (volume.at(from_start ? step : n - 1 - step, j, k) != value) return step;
  return -1;
}

// Whether the voxels of `value` reached from the rows' sides end in the same place in two slices
// half the field's height apart. Padding at air's own value surrounds the scanner's cylinder,
// the same in every slice, and ends where the noisy air inside it starts; air a scanner clamps to
// that one value (the cadaver head's) surrounds the head, whose outline changes with the height.
bool value_surrounds_a_cylinder(const Volume& volume, int value) {
  const auto& g = volume.geometry;
  std::vector<int> slices;  // the slices the value does not fill (the field's height)
  for (int k = 0; k < g.size.z(); ++k)
    if (run_from_side(volume, value, g.size.y() / 2, k, true) >= 0) slices.push_back(k);
  if (slices.size() < 4) return false;
  const int k1 = slices[slices.size() / 4], k2 = slices[3 * slices.size() / 4];
  int compared = 0, same = 0;
  for (int j = 0; j < g.size.y(); ++j)
    for (bool from_start : {true, false}) {
      const int a = run_from_side(volume, value, j, k1, from_start),
                b = run_from_side(volume, value, j, k2, from_start);
      if (a <= 0 || b <= 0) continue;  // a full row, or none of the value at its side
      ++compared;
      same += std::abs(a - b) <= 1;
    }
  return compared >= 20 && same >= 0.9 * compared;
}

// Whether `value` is a spike near the grid's axis too (within 40 % of the smaller half-width):
// a scanner reconstructs there, so the spike is the air of a scan without noise (a synthetic
// one), not padding.
bool spike_near_the_axis(const Volume& volume, int value) {
  const auto& g = volume.geometry;
  const double ci = (g.size.x() - 1) / 2.0, cj = (g.size.y() - 1) / 2.0;
  const double reach = 0.4 * std::min(ci * g.spacing.x(), cj * g.spacing.y());
  int64_t at = 0, below = 0, above = 0;
  for (int k = 0; k < g.size.z(); k += 2)
    for (int j = 0; j < g.size.y(); j += 2)
      for (int i = 0; i < g.size.x(); i += 2) {
        if (std::hypot((i - ci) * g.spacing.x(), (j - cj) * g.spacing.y()) > reach) continue;
        const int v = volume.at(i, j, k);
        at += v == value, below += v == value - 1, above += v == value + 1;
      }
  return at > 2 * std::max(below, above) + 10;
}

// The counts of every value (`full`, indexed by value + 32768) over their central 99.8 %
// (`left_out` not counted), smoothed over 5 bins so
// that noise makes no peaks.
Histogram histogram_of(std::vector<int64_t> full, std::optional<int> left_out) {
  if (left_out) full[size_t(*left_out + 32768)] = 0;
  int64_t total = 0;
  for (int64_t count : full) total += count;
  auto percentile = [&](double share) {
    int64_t seen = 0;
    for (size_t v = 0; v < full.size(); ++v)
      if ((seen += full[v]) > int64_t(share * double(total))) return int(v) - 32768;
    return 32767;
  };
  Histogram h;
  h.low = percentile(0.001);
  const int high = percentile(0.999);
  h.width = std::max(1.0, double(high - h.low + 1) / kBins);
  std::vector<double> raw(kBins, 0);
  for (int v = h.low; v <= high; ++v)
    raw[std::min<size_t>(kBins - 1, size_t((v - h.low) / h.width))] += double(full[size_t(v + 32768)]);
  h.counts.assign(kBins, 0);
  for (int b = 0; b < kBins; ++b)
    for (int d = -2; d <= 2; ++d)
      if (b + d >= 0 && b + d < kBins) h.counts[size_t(b)] += raw[size_t(b + d)];
  return h;
}

// The highest local maxima, separated by at least `gap` bins, highest first.
std::vector<size_t> peaks_of(const Histogram& h, size_t gap) {
  std::vector<size_t> maxima;
  for (size_t b = 1; b + 1 < h.counts.size(); ++b)
    if (h.counts[b] > 0 && h.counts[b] >= h.counts[b - 1] && h.counts[b] > h.counts[b + 1]) maxima.push_back(b);
  std::stable_sort(maxima.begin(), maxima.end(), [&](size_t a, size_t b) { return h.counts[a] > h.counts[b]; });
  std::vector<size_t> kept;
  for (size_t m : maxima)
    if (std::all_of(kept.begin(), kept.end(), [&](size_t k) { return (m > k ? m - k : k - m) >= gap; }))
      kept.push_back(m);
  return kept;
}

}  // namespace

bool GreyCalibration::is_hounsfield(double tolerance_hu) const {
  return std::abs(air + 1000) <= tolerance_hu && std::abs(soft_tissue - 40) <= tolerance_hu;
}

std::string GreyCalibration::describe() const {
  char text[160];
  if (!from_histogram) return "no air and soft-tissue modes found: the values are taken as HU";
  std::snprintf(text, sizeof text, "air at %.0f and soft tissue at %.0f in the scan's values%s", air, soft_tissue,
                is_hounsfield() ? " (Hounsfield units as stored)" : ", mapped to -1000 and 40 HU");
  return text;
}

GreyCalibration estimate_grey_calibration(const Volume& volume) {
  GreyCalibration calibration;
  if (volume.hu.empty()) return calibration;
  std::vector<int64_t> full(65536, 0);
  for (int16_t v : volume.hu) ++full[size_t(int(v) + 32768)];
  const int64_t total = int64_t(volume.hu.size());
  // Padding below air, or at air's own value around a cylinder; a spike that stands near the
  // grid's axis too is the air of a scan without noise.
  const std::optional<int> below_air = lowest_value_spike(full, total);
  calibration.padding = below_air;
  if (!below_air)
    if (const auto most = most_frequent_value_spike(full, total); most && value_surrounds_a_cylinder(volume, *most))
      calibration.padding = most;
  if (calibration.padding && spike_near_the_axis(volume, *calibration.padding)) calibration.padding.reset();
  // Padding below air is left out of the histogram; at air's own value it stays (it moves no mode).
  const Histogram h = histogram_of(full, below_air ? calibration.padding : std::nullopt);
  // Air and soft tissue lie about 1000 HU apart, a large share of any head scan's range: peaks
  // closer than a tenth of the range are one tissue's noise or fat beside muscle.
  const auto peaks = peaks_of(h, kBins / 10);
  if (peaks.size() < 2) return calibration;
  const double first = h.centre(peaks[0]), second = h.centre(peaks[1]);
  calibration.air = std::min(first, second);
  calibration.soft_tissue = std::max(first, second);
  calibration.from_histogram = true;
  return calibration;
}

}  // namespace maxillo
