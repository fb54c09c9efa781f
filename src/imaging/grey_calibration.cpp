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
// a CT's outside its circle) with one value at or below air's. That value is a spike at the
// bottom of the histogram, no tissue (tissue is noisy): it is left out, or it would be taken for air.
std::optional<int> leave_out_padding(std::vector<int64_t>& full, int64_t total) {
  size_t lowest = 0;
  while (lowest + 1 < full.size() && full[lowest] == 0) ++lowest;
  const int64_t next_up = lowest + 1 < full.size() ? full[lowest + 1] : 0;
  if (full[lowest] <= total / 50 || full[lowest] <= 20 * next_up) return std::nullopt;
  full[lowest] = 0;
  return int(lowest) - 32768;
}

// Counts over the central 99.8 % of values, smoothed over 5 bins so that noise makes no peaks.
Histogram histogram_of(const Volume& volume, std::optional<int>& padding) {
  std::vector<int64_t> full(65536, 0);
  for (int16_t v : volume.hu) ++full[size_t(int(v) + 32768)];
  padding = leave_out_padding(full, int64_t(volume.hu.size()));
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
  const Histogram h = histogram_of(volume, calibration.padding);
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
