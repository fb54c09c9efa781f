#include "landmarking/symmetry_plane.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/angles.h"
#include "core/parallel_slabs.h"
#include "imaging/distance_morphology.h"
#include "core/volume_resample.h"

namespace maxillo::landmarking {
namespace {

constexpr double kTruncationMm = 8;     // a mirrored point farther from the surface counts as this far
constexpr size_t kSearchPoints = 4000;  // points used by the grid search (all by the refinement)

// A candidate plane as two tilts (radians) of the initial normal towards two directions across
// it, and a shift (mm) of its offset along the normal.
struct Candidate {
  double tilt_u = 0, tilt_v = 0, shift = 0;
};

class PlaneFamily {
 public:
  explicit PlaneFamily(const Plane& initial) : normal_(initial.normal.normalized()) {
    const Eigen::Vector3d helper = std::abs(normal_.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
    u_ = helper.cross(normal_).normalized();
    v_ = normal_.cross(u_);
    centre_ = initial.offset * normal_;
  }
  Plane plane(const Candidate& c) const {
    Plane p;
    p.normal = (normal_ + std::tan(c.tilt_u) * u_ + std::tan(c.tilt_v) * v_).normalized();
    p.offset = p.normal.dot(centre_) + c.shift;
    return p;
  }

 private:
  Eigen::Vector3d normal_, u_, v_, centre_;
};

// Mean truncated distance of the mirrored points to the surface: 0 for a perfect mirror image.
double asymmetry(const Plane& plane, std::span<const Eigen::Vector3d> points, const SurfaceDistance& surface) {
  double sum = 0;
  for (const auto& p : points) sum += std::min(surface.at(plane.mirrored(p)), kTruncationMm);
  return points.empty() ? 0 : sum / double(points.size());
}

// Every k-th point, k chosen so that at most `count` remain (deterministic).
std::vector<Eigen::Vector3d> every_kth(std::span<const Eigen::Vector3d> points, size_t count) {
  const size_t step = std::max<size_t>(1, (points.size() + count - 1) / count);
  std::vector<Eigen::Vector3d> kept;
  for (size_t i = 0; i < points.size(); i += step) kept.push_back(points[i]);
  return kept;
}

Candidate grid_search(const PlaneFamily& family, std::span<const Eigen::Vector3d> points,
                      const SurfaceDistance& surface) {
  std::vector<Candidate> candidates;
  for (int a = -6; a <= 6; ++a)
    for (int b = -6; b <= 6; ++b)
      for (int s = -4; s <= 4; ++s) candidates.push_back({4.0 * a * kDeg, 4.0 * b * kDeg, 3.0 * s});
  std::vector<double> scores(candidates.size());
  for_each_part(int(candidates.size()),
                [&](int i) { scores[size_t(i)] = asymmetry(family.plane(candidates[size_t(i)]), points, surface); });
  // The first of equal scores: the order of the list, never of the threads, decides.
  return candidates[size_t(std::min_element(scores.begin(), scores.end()) - scores.begin())];
}

// Coordinate pattern search: each parameter tried one step either way, steps halved when
// nothing improves, until they are below 0.01 degree and 0.01 mm.
Candidate refine(const PlaneFamily& family, Candidate best, double angle_step, double shift_step,
                 const std::function<double(const Plane&)>& score, double& best_score) {
  best_score = score(family.plane(best));
  while (angle_step > 0.01 * kDeg || shift_step > 0.01) {
    bool improved = false;
    for (int parameter = 0; parameter < 3; ++parameter)
      for (int sign : {-1, 1}) {
        Candidate trial = best;
        double& value = parameter == 0 ? trial.tilt_u : parameter == 1 ? trial.tilt_v : trial.shift;
        value += sign * (parameter == 2 ? shift_step : angle_step);
        const double trial_score = score(family.plane(trial));
        if (trial_score < best_score) {
          best_score = trial_score;
          best = trial;
          improved = true;
        }
      }
    if (!improved) {
      angle_step /= 2;
      shift_step /= 2;
    }
  }
  return best;
}

}  // namespace

SurfaceDistance::SurfaceDistance(const Mask& surface, const MaskGrid& grid, const Eigen::Vector3d& origin)
    : distance_(squared_distance_to(surface, grid)), grid_(grid), origin_(origin) {
  for (float& d : distance_) d = std::sqrt(d);
}

double SurfaceDistance::at(const Eigen::Vector3d& p) const {
  double index[3];
  size_t base[3];
  double weight[3];
  for (int a = 0; a < 3; ++a) {
    index[a] = (p[a] - origin_[a]) / grid_.spacing[size_t(a)];
    const double last = double(grid_.size[size_t(a)]) - 1.001;
    if (index[a] < 0 || index[a] > last) return kTruncationMm;  // outside the map: as far as counts
    base[a] = size_t(index[a]);
    weight[a] = index[a] - double(base[a]);
  }
  double value = 0;
  for (int corner = 0; corner < 8; ++corner) {
    double w = 1;
    size_t at[3];
    for (int a = 0; a < 3; ++a) {
      const bool upper = (corner >> a) & 1;
      at[a] = base[a] + (upper ? 1 : 0);
      w *= upper ? weight[a] : 1 - weight[a];
    }
    value += w * distance_[grid_.index(at[0], at[1], at[2])];
  }
  return value;
}

SymmetryPlane find_symmetry_plane(std::span<const Eigen::Vector3d> points, const SurfaceDistance& surface,
                                  const Plane& initial) {
  const PlaneFamily family(initial);
  const auto few = every_kth(points, kSearchPoints);
  const Candidate start = grid_search(family, few, surface);
  SymmetryPlane result;
  const auto score = [&](const Plane& plane) { return asymmetry(plane, points, surface); };
  result.plane = family.plane(refine(family, start, 2 * kDeg, 1.5, score, result.mean_distance_mm));
  return result;
}

Plane refine_on_grey_values(const Volume& ct, const GreyCalibration& grey, std::span<const Eigen::Vector3d> points,
                            const Plane& start) {
  const PlaneFamily family(start);
  const double low = grey.from_hu(-200), high = grey.from_hu(1600);
  // The points' own values once; their mirror images' for each candidate.
  std::vector<double> values(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    values[i] = std::clamp(sample_trilinear(ct, points[i], grey.air), low, high);
  const auto score = [&](const Plane& plane) {
    std::vector<double> parts(16, 0.0);
    for_each_part(16, [&](int part) {
      const PartRange range = part_range(int64_t(points.size()), part, 16);
      for (int64_t i = range.begin; i < range.end; ++i)
        parts[size_t(part)] +=
            std::abs(values[size_t(i)] -
                     std::clamp(sample_trilinear(ct, plane.mirrored(points[size_t(i)]), grey.air), low, high));
    });
    double sum = 0;
    for (double p : parts) sum += p;  // joined in part order: the same bits whatever the threads
    return sum;
  };
  double best_score = 0;
  return family.plane(refine(family, Candidate{}, 0.5 * kDeg, 0.5, score, best_score));
}

}  // namespace maxillo::landmarking
