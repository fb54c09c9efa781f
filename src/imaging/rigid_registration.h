#pragma once
// Rigid registration of a post-operative CT (moving) to the pre-operative CT (fixed) by Mattes
// mutual information on an unaltered subvolume, with ITK (itk_registration.cpp does the ITK part;
// this header speaks maxillo types only).
//
// moving_to_fixed maps a point in the moving CT's LPS frame (mm) onto the same anatomy in the
// fixed CT's LPS frame. The metric is evaluated only at fixed-CT points inside the box: the
// surgery changes the face and jaws, so the box should hold bone the operation did not touch
// (by default the cranium above the infraorbital rim, cranial_registration_box). Inside the box,
// voxels of plain air (HU < -900) not touching anything denser are not sampled either.
//
// Start: `initial` when it is not the identity; otherwise the translation that puts the moving
// CT's tissue centroid (HU >= -400, a moments initialisation that ignores air) on the fixed
// CT's, inside the box's S range where the moving CT reaches it. The rotation centre is the
// box centre.
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>

#include "ceph/landmark.h"
#include "core/volume.h"

namespace maxillo {

struct RegistrationBox {
  Eigen::Vector3d min, max;  // LPS mm, axis-aligned
};

// Defaults tuned on the real cadaver head (`maxillo bench register`): 0.02-0.03 mm RMS over the
// skin for a 4 degree / 7 mm move in about 3 s on 2 cores.
struct RigidRegistrationOptions {
  std::optional<RegistrationBox> box;  // metric only inside it (fixed image mask); none = whole overlap
  int levels = 3;                      // 2x2x2 block-mean pyramid: voxels 4x, 2x, 1x the fixed CT's
  int histogram_bins = 32;             // Mattes joint histogram (elastix's usual 32; 50 was noisier)
  double sampling_fraction = 0.01;     // of the fixed voxels at full resolution (x4 and x16 on the
                                       // shrunk levels), kept where the mask holds more than air
  int max_iterations_per_level = 200;  // the finest level using all of them = did not converge
  double convergence = 1e-6;           // full resolution stops when the metric's normalised slope over
  int convergence_window = 6;          // the last convergence_window iterations falls below this
  double coarse_convergence = 1e-3;    // the same on the shrunk levels (they only need to get close)
  bool regular_sampling = true;        // samples on a jittered regular grid (less noisy than random)
  uint32_t seed = 1;                   // sample jitter
  // Threads ITK may use (0 = ITK's default, one per core). The default is 1 because a
  // validation tool must give one answer: ITK 5.2's Mattes metric, for a global transform, flushes
  // each thread's joint-histogram derivatives into the shared sum under a try-lock, in whatever
  // order the threads get there, so with 2 threads repeated runs on the cadaver head differed by
  // up to 0.011 deg (0.015 mm over the skin) and on a real pre/post pair by 0.1-0.2 deg. One
  // thread sums in sample order: the same inputs give the same bits (2.0 s instead of 1.1 s on
  // the cadaver head, `maxillo bench register --same-seed --threads 0|1`).
  int threads = 1;
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();  // moving_to_fixed guess
};

struct RigidRegistrationResult {
  Eigen::Isometry3d moving_to_fixed = Eigen::Isometry3d::Identity();
  double metric = 0;  // final Mattes mutual information, negated as ITK reports it (lower = better)
  int iterations = 0;  // optimiser iterations over all levels
  double seconds = 0;  // wall time of register_rigid
};

// Throws Error(kBadValue, "fixed CT"/"moving CT"/"registration box", reason) for an empty volume
// or a box that holds no voxel of the fixed CT; Error(kProcessing, "registration", reason) when
// the optimiser ends at its iteration limit without converging on the finest level or ITK fails.
RigidRegistrationResult register_rigid(const Volume& fixed, const Volume& moving,
                                       const RigidRegistrationOptions& options = {});

// The default subvolume: the cranium above the infraorbital rim, the whole fixed image in x and y.
// With orbitale landmarks (Or, or OrR/OrL, or Or_R/Or_L: their mean) the box starts
// kAboveOrbitaleMm above their mean height; without, it is the top kCranialFraction of the S
// extent of the tissue (HU >= -400) in the fixed CT (in an adult head the orbital floor lies
// about 45-50 % of the way down from the vertex to the chin, so the top 45 % is above it).
inline constexpr double kAboveOrbitaleMm = 5;
inline constexpr double kCranialFraction = 0.45;
RegistrationBox cranial_registration_box(const Volume& fixed, const LandmarkSet* landmarks = nullptr);

// The world (LPS) bounding box of the volume's voxel centres.
RegistrationBox volume_bounds(const VolumeGeometry& geometry);

}  // namespace maxillo
