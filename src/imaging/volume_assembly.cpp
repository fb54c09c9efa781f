// Series assembly: consistency checks, sorting along the slice normal, uniform-grid resampling.
#include "imaging/volume_assembly.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "core/progress.h"

namespace maxillo {
namespace {

constexpr double kOrientationTolerance = 1e-4;  // per IOP component (DS values round at ~1e-6)
constexpr double kSpacingTolerance = 1e-4;      // relative, in-plane pixel spacing
constexpr double kDuplicateFraction = 0.01;     // of the median gap
constexpr double kMissingFactor = 1.5;          // gap / median gap
constexpr double kJitterFraction = 0.05;        // of the spacing: tolerated deviation from uniform
constexpr double kTiltToleranceFraction = 0.1;  // in-plane drift, as a fraction of a pixel

[[noreturn]] void refuse(const DicomSlice& slice, const std::string& reason) {
  throw Error(ErrorCode::kInconsistentSeries, slice.path.string(), reason);
}

std::string mm(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value << " mm";
  return out.str();
}

void check_same_frame(const std::vector<DicomSlice>& slices) {
  const DicomSlice& first = slices.front();
  for (const DicomSlice& s : slices) {
    if (s.series_instance_uid != first.series_instance_uid)
      refuse(s, "belongs to series " + s.series_instance_uid + ", not " + first.series_instance_uid + " (of " +
                    first.path.filename().string() + ")");
    if ((s.row_direction - first.row_direction).cwiseAbs().maxCoeff() > kOrientationTolerance ||
        (s.column_direction - first.column_direction).cwiseAbs().maxCoeff() > kOrientationTolerance)
      refuse(s, "image orientation differs from " + first.path.filename().string() + " (mixed orientations)");
    if (s.rows != first.rows || s.columns != first.columns)
      refuse(s, "image is " + std::to_string(s.columns) + "x" + std::to_string(s.rows) + ", " +
                    first.path.filename().string() + " is " + std::to_string(first.columns) + "x" +
                    std::to_string(first.rows));
    if (std::abs(s.row_spacing / first.row_spacing - 1) > kSpacingTolerance ||
        std::abs(s.column_spacing / first.column_spacing - 1) > kSpacingTolerance)
      refuse(s, "pixel spacing differs from " + first.path.filename().string());
  }
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// Positions along the normal must increase by comparable steps; returns the gaps.
std::vector<double> checked_gaps(const std::vector<DicomSlice>& slices, const std::vector<double>& along) {
  std::vector<double> gaps;
  for (size_t n = 1; n < slices.size(); ++n) gaps.push_back(along[n] - along[n - 1]);
  const double typical = median(gaps);
  for (size_t n = 0; n < gaps.size(); ++n) {
    const std::string neighbours =
        slices[n].path.filename().string() + " and " + slices[n + 1].path.filename().string();
    if (gaps[n] <= kDuplicateFraction * typical)
      refuse(slices[n + 1], "same position as " + slices[n].path.filename().string() + " (duplicate slice, " +
                                mm(gaps[n]) + " apart)");
    if (gaps[n] > kMissingFactor * typical)
      refuse(slices[n + 1], "gap of " + mm(gaps[n]) + " between " + neighbours + " at " + mm(along[n]) + " to " +
                                mm(along[n + 1]) + " along the normal, median spacing " + mm(typical) +
                                " (missing slices)");
  }
  return gaps;
}

// Refuses positions that drift within the image plane (gantry tilt or a broken series).
void check_on_normal_line(const std::vector<DicomSlice>& slices, const Eigen::Vector3d& normal) {
  const double pixel = std::min(slices.front().row_spacing, slices.front().column_spacing);
  for (const DicomSlice& s : slices) {
    Eigen::Vector3d offset = s.position - slices.front().position;
    double along = offset.dot(normal);
    double across = (offset - along * normal).norm();
    if (across > kTiltToleranceFraction * pixel) {
      double angle = std::atan2(across, std::abs(along)) * 180 / std::numbers::pi;
      std::ostringstream reason;
      reason.precision(3);
      reason << "slice positions are not along the slice normal: shifted " << across << " mm within the plane over "
             << std::abs(along) << " mm, a gantry tilt of " << angle << " degrees";
      if (s.gantry_tilt_degrees) reason << " (Gantry/Detector Tilt says " << *s.gantry_tilt_degrees << ")";
      reason << "; tilted series are not supported";
      refuse(s, reason.str());
    }
  }
}

Volume stack_as_is(std::vector<DicomSlice>& slices, const std::vector<double>& along, VolumeGeometry g) {
  const size_t plane = size_t(g.size.x()) * g.size.y();
  g.spacing.z() = (along.back() - along.front()) / double(slices.size() - 1);
  Volume volume{g, {}};
  volume.hu.resize(plane * slices.size());
  for (size_t k = 0; k < slices.size(); ++k) {
    std::copy(slices[k].hu.begin(), slices[k].hu.end(), volume.hu.begin() + plane * k);
    std::vector<int16_t>().swap(slices[k].hu);  // release as we go: a CT series is ~0.5 GB
  }
  return volume;
}

Volume resample_uniform(const std::vector<DicomSlice>& slices, const std::vector<double>& along, double step,
                        VolumeGeometry g) {
  const size_t plane = size_t(g.size.x()) * g.size.y();
  const int count = int(std::floor((along.back() - along.front()) / step + 1e-6)) + 1;
  g.size.z() = count;
  g.spacing.z() = step;
  Volume volume{g, std::vector<int16_t>(plane * count)};
  size_t below = 0;
  for (int k = 0; k < count; ++k) {
    double target = along.front() + k * step;
    while (below + 2 < slices.size() && along[below + 1] <= target) ++below;
    double w = std::clamp((target - along[below]) / (along[below + 1] - along[below]), 0.0, 1.0);
    const auto& a = slices[below].hu;
    const auto& b = slices[below + 1].hu;
    int16_t* out = volume.hu.data() + plane * k;
    for (size_t n = 0; n < plane; ++n) out[n] = int16_t(std::lround((1 - w) * a[n] + w * b[n]));
  }
  return volume;
}

}  // namespace

Volume assemble_volume(std::vector<DicomSlice> slices, AssemblyReport* report) {
  if (slices.size() < 3)
    throw Error(ErrorCode::kInconsistentSeries, slices.empty() ? "" : slices.front().path.string(),
                "a volume needs at least 3 slices, the series has " + std::to_string(slices.size()));
  check_same_frame(slices);
  const Eigen::Vector3d normal = slices.front().normal().normalized();
  std::sort(slices.begin(), slices.end(),
            [&](const DicomSlice& a, const DicomSlice& b) { return a.position.dot(normal) < b.position.dot(normal); });
  std::vector<double> along;
  for (const DicomSlice& s : slices) along.push_back(s.position.dot(normal));
  const std::vector<double> gaps = checked_gaps(slices, along);
  check_on_normal_line(slices, normal);

  const DicomSlice& first = slices.front();
  VolumeGeometry g;
  g.size = {first.columns, first.rows, int(slices.size())};
  g.spacing = {first.column_spacing, first.row_spacing, 0};
  g.origin = first.position;
  g.direction.col(0) = first.row_direction;
  g.direction.col(1) = first.column_direction;
  g.direction.col(2) = normal;

  const double uniform_step = (along.back() - along.front()) / double(slices.size() - 1);
  double deviation = 0;
  for (size_t k = 0; k < slices.size(); ++k)
    deviation = std::max(deviation, std::abs(along[k] - (along.front() + k * uniform_step)));
  const bool uniform = deviation <= kJitterFraction * uniform_step;
  if (report) *report = {int(slices.size()), uniform ? SliceSpacing::Uniform : SliceSpacing::Resampled, deviation};
  return uniform ? stack_as_is(slices, along, g) : resample_uniform(slices, along, median(gaps), g);
}

Volume load_series_volume(const std::vector<std::filesystem::path>& files, AssemblyReport* report) {
  std::vector<DicomSlice> slices;
  slices.reserve(files.size());
  Progress progress("reading slices", files.size());
  for (const auto& file : files) {
    slices.push_back(read_dicom_slice(file));
    progress.advance();
  }
  progress.finish();
  return assemble_volume(std::move(slices), report);
}

}  // namespace maxillo
