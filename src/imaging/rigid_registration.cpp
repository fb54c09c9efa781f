// Rigid registration: maxillo types <-> the ITK part (itk_registration.cpp), the default box and
// the starting pose. Eigen only, no ITK here (see itk_registration.h for why).
#include "imaging/rigid_registration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/error.h"
#include "geometry/rigid_fit.h"
#include "imaging/itk_registration.h"
#include "imaging/registration_samples.h"

namespace maxillo {
namespace {

constexpr double kTissueHu = -400;  // air below, skin and everything inside above (see segmentation.h)

itk_registration::Image to_plain_image(const Volume& volume) {
  itk_registration::Image image;
  const VolumeGeometry& g = volume.geometry;
  for (int a = 0; a < 3; ++a) {
    image.grid.size[size_t(a)] = size_t(g.size[a]);
    image.grid.spacing[size_t(a)] = g.spacing[a];
    image.origin[size_t(a)] = g.origin[a];
    for (int c = 0; c < 3; ++c) image.direction[size_t(3 * a + c)] = g.direction(a, c);
  }
  image.hu = volume.hu.data();
  return image;
}

void check_volume(const Volume& volume, const std::string& name) {
  const VolumeGeometry& g = volume.geometry;
  if (g.size.minCoeff() < 4)
    throw Error(ErrorCode::kBadValue, name,
                "volume of " + std::to_string(g.size.x()) + "x" + std::to_string(g.size.y()) + "x" +
                    std::to_string(g.size.z()) + " voxels is too small to register (at least 4 along each axis)");
  if (int64_t(volume.hu.size()) != g.voxel_count())
    throw Error(ErrorCode::kBadValue, name, "voxel buffer does not match the volume's size");
}

// 1 at the fixed voxels whose centre lies inside the box.
itk_filters::Mask box_mask(const VolumeGeometry& g, const RegistrationBox& box, int64_t* inside) {
  itk_filters::Mask mask(size_t(g.voxel_count()), 0);
  *inside = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        if ((p.array() >= box.min.array()).all() && (p.array() <= box.max.array()).all()) {
          mask[size_t(g.index(i, j, k))] = 1;
          ++*inside;
        }
      }
  return mask;
}

// The voxels of the mask where the metric is sampled: those that are not plain air (HU >=
// kSampledHu) or that touch such a voxel. Air far from the head carries no information about
// the pose, and in a head CT it fills about half of the box: leaving it out doubles the useful
// samples for the same time. The skin's air side stays (the neighbours of tissue).
constexpr double kSampledHu = -900;
void keep_informative_voxels(const Volume& fixed, itk_filters::Mask& mask) {
  const VolumeGeometry& g = fixed.geometry;
  auto informative = [&](int i, int j, int k) { return g.contains(i, j, k) && fixed.at(i, j, k) >= kSampledHu; };
  itk_filters::Mask kept(mask.size(), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const size_t n = size_t(g.index(i, j, k));
        if (!mask[n]) continue;
        kept[n] = informative(i, j, k) || informative(i - 1, j, k) || informative(i + 1, j, k) ||
                  informative(i, j - 1, k) || informative(i, j + 1, k) || informative(i, j, k - 1) ||
                  informative(i, j, k + 1);
      }
  mask.swap(kept);
}

// Centroid of the tissue voxels (HU >= kTissueHu) with z in [z_min, z_max]; nullopt when none.
std::optional<Eigen::Vector3d> tissue_centroid(const Volume& volume, double z_min, double z_max) {
  const VolumeGeometry& g = volume.geometry;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int64_t count = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        if (volume.at(i, j, k) < kTissueHu) continue;
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        if (p.z() < z_min || p.z() > z_max) continue;
        sum += p;
        ++count;
      }
  if (count == 0) return std::nullopt;
  return sum / double(count);
}

// The moments start: translate the moving tissue's centroid onto the fixed tissue's, both taken
// over the box's S range (a post-operative scan often covers less of the neck or the vertex, so
// centroids of the whole scans would differ by that). Identity when either has no tissue there.
Eigen::Isometry3d centroid_start(const Volume& fixed, const Volume& moving, const RegistrationBox& box) {
  const auto fixed_centre = tissue_centroid(fixed, box.min.z(), box.max.z());
  const auto moving_centre = tissue_centroid(moving, box.min.z(), box.max.z());
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  if (fixed_centre && moving_centre) start.translation() = *fixed_centre - *moving_centre;
  return start;
}

// moving_to_fixed as ITK's fixed -> moving map about `centre`.
itk_registration::RigidMap to_itk_map(const Eigen::Isometry3d& moving_to_fixed, const Eigen::Vector3d& centre) {
  const Eigen::Isometry3d fixed_to_moving = moving_to_fixed.inverse();
  itk_registration::RigidMap map;
  const Eigen::Matrix3d r = fixed_to_moving.linear();
  // p_moving = R (p - c) + c + t  =>  t = R c + translation - c.
  const Eigen::Vector3d t = fixed_to_moving * centre - centre;
  for (int a = 0; a < 3; ++a) {
    map.centre[size_t(a)] = centre[a];
    map.translation[size_t(a)] = t[a];
    for (int c = 0; c < 3; ++c) map.matrix[size_t(3 * a + c)] = r(a, c);
  }
  return map;
}

Eigen::Isometry3d from_itk_map(const itk_registration::RigidMap& map) {
  Eigen::Matrix3d r;
  Eigen::Vector3d centre, t;
  for (int a = 0; a < 3; ++a) {
    centre[a] = map.centre[size_t(a)];
    t[a] = map.translation[size_t(a)];
    for (int c = 0; c < 3; ++c) r(a, c) = map.matrix[size_t(3 * a + c)];
  }
  // Re-orthonormalise: ITK's versor matrix is orthonormal to ~1e-15 already; this keeps it so.
  Eigen::Isometry3d fixed_to_moving = Eigen::Isometry3d::Identity();
  fixed_to_moving.linear() = nearest_rotation(r);
  fixed_to_moving.translation() = centre + t - fixed_to_moving.linear() * centre;
  return fixed_to_moving.inverse();
}

// The S extent [z_low, z_high] of the tissue: the heights of the grid planes (k) that hold at
// least ~1 cm2 of tissue voxels.
std::pair<double, double> tissue_z_extent(const Volume& volume) {
  const VolumeGeometry& g = volume.geometry;
  double z_low = std::numeric_limits<double>::infinity(), z_high = -z_low;
  // A slab with fewer tissue voxels than ~1 cm2 is noise, a table edge or a cable, not the head.
  const double voxel_area = g.spacing.x() * g.spacing.y();
  const int64_t min_voxels = std::max<int64_t>(1, int64_t(std::ceil(100.0 / voxel_area)));
  for (int k = 0; k < g.size.z(); ++k) {
    int64_t tissue = 0;
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) tissue += volume.at(i, j, k) >= kTissueHu;
    if (tissue < min_voxels) continue;
    // The plane's z range (a tilted grid spans several heights; take its corners).
    for (int cj : {0, g.size.y() - 1})
      for (int ci : {0, g.size.x() - 1}) {
        const double z = g.world(Eigen::Vector3d(ci, cj, k)).z();
        z_low = std::min(z_low, z);
        z_high = std::max(z_high, z);
      }
  }
  if (z_low > z_high)
    throw Error(ErrorCode::kBadValue, "fixed CT", "no tissue (HU >= -400) to place the registration box");
  return {z_low, z_high};
}

std::optional<Eigen::Vector3d> orbitale(const LandmarkSet& landmarks) {
  if (auto both = bilateral_mean(landmarks, "Or")) return both;
  auto right = find_landmark(landmarks, "Or_R"), left = find_landmark(landmarks, "Or_L");
  if (right && left) return 0.5 * (*right + *left);
  return right ? right : left;
}

}  // namespace

RegistrationBox volume_bounds(const VolumeGeometry& g) {
  RegistrationBox bounds{Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()),
                         Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity())};
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d ijk((corner & 1) ? g.size.x() - 1 : 0, (corner & 2) ? g.size.y() - 1 : 0,
                              (corner & 4) ? g.size.z() - 1 : 0);
    const Eigen::Vector3d p = g.world(ijk);
    bounds.min = bounds.min.cwiseMin(p);
    bounds.max = bounds.max.cwiseMax(p);
  }
  return bounds;
}

RegistrationBox cranial_registration_box(const Volume& fixed, const LandmarkSet* landmarks) {
  check_volume(fixed, "fixed CT");
  RegistrationBox box = volume_bounds(fixed.geometry);
  const std::optional<Eigen::Vector3d> orbit = landmarks ? orbitale(*landmarks) : std::nullopt;
  if (orbit) {
    box.min.z() = orbit->z() + kAboveOrbitaleMm;
  } else {
    const auto [z_low, z_high] = tissue_z_extent(fixed);
    box.min.z() = z_high - kCranialFraction * (z_high - z_low);
    box.max.z() = std::min(box.max.z(), z_high);
  }
  if (box.min.z() >= box.max.z())
    throw Error(
        ErrorCode::kBadValue, "registration box",
        "orbitale (z = " + std::to_string(orbit ? orbit->z() : 0.0) + " mm) is at or above the top of the fixed CT");
  return box;
}

RigidRegistrationResult register_rigid(const Volume& fixed, const Volume& moving,
                                       const RigidRegistrationOptions& options) {
  const auto start_time = std::chrono::steady_clock::now();
  check_volume(fixed, "fixed CT");
  check_volume(moving, "moving CT");
  const RegistrationBox box = options.box ? *options.box : volume_bounds(fixed.geometry);
  if ((box.min.array() >= box.max.array()).any())
    throw Error(ErrorCode::kBadValue, "registration box", "min must be below max along every axis");

  int64_t inside = 0;
  itk_filters::Mask mask = box_mask(fixed.geometry, box, &inside);
  // Mattes MI needs enough samples for its histogram even on the coarsest level.
  const int64_t min_voxels = int64_t(1) << (3 * std::max(0, options.levels - 1)) << 9;
  if (inside < min_voxels)
    throw Error(ErrorCode::kBadValue, "registration box",
                std::to_string(inside) + " voxels of the fixed CT inside it (at least " + std::to_string(min_voxels) +
                    " needed): the box is outside the image or too small");

  const Eigen::Isometry3d initial =
      options.initial.isApprox(Eigen::Isometry3d::Identity()) ? centroid_start(fixed, moving, box) : options.initial;
  keep_informative_voxels(fixed, mask);
  itk_registration::Settings settings;
  // Level l has voxels 2^l times the CT's; the same seed gives each level its own pattern.
  for (int level = 0; level < std::max(1, options.levels); ++level)
    settings.samples.push_back(
        metric_samples(fixed.geometry, mask,
                       {.fraction = options.sampling_fraction,
                        .level_factor = 1 << level,
                        .pattern = options.regular_sampling ? SamplePattern::kJitteredGrid : SamplePattern::kRandom,
                        .seed = options.seed}));
  settings.histogram_bins = options.histogram_bins;
  settings.low = options.intensity_low;
  settings.high = options.intensity_high;
  settings.max_iterations_per_level = options.max_iterations_per_level;
  settings.fine_step_mm = options.convergence;
  settings.window = options.convergence_window;
  settings.coarse_convergence = options.coarse_convergence;
  settings.threads = options.threads;
  settings.initial = to_itk_map(initial, 0.5 * (box.min + box.max));

  const itk_registration::Outcome outcome =
      itk_registration::register_rigid(to_plain_image(fixed), to_plain_image(moving), settings);
  if (!outcome.converged)
    throw Error(ErrorCode::kProcessing, "registration",
                "did not converge: the finest level used all " + std::to_string(settings.max_iterations_per_level) +
                    " iterations (the CTs may not overlap, or the start is too far off)");

  RigidRegistrationResult result;
  result.moving_to_fixed = from_itk_map(outcome.fixed_to_moving);
  result.metric = outcome.metric;
  result.iterations = outcome.iterations;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

}  // namespace maxillo
