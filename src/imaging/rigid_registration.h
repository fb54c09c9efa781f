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
//
// One answer (issue 14, defect 12): the same inputs give the same bits whatever the threads do
// and however many there are (the metric's sums are made in a fixed order), and a copy of a CT
// that differs only in how it is stored (slice order, origin convention, padding values beyond
// the histogram range, rescale or pixel type, as long as the HU are the same) gives the same
// answer to ~1e-8 deg: the samples are chosen by anatomy, not by storage order; the histograms
// span a fixed HU range; the metric is smooth (cubic B-spline) with its exact gradient; and the
// full-resolution level is minimised until the transform stands still, from the samples that
// stay inside the moving CT at the answer. Before, three runs on a real pre/post pair differed
// by 0.1-0.2 deg and a separately converted copy by 0.43 deg.
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>

#include "ceph/landmark.h"
#include "core/volume.h"

namespace maxillo {

struct RegistrationBox {
  Eigen::Vector3d min, max;  // LPS mm, axis-aligned
};

// Defaults tuned on the real cadaver head (`maxillo bench register`): ~0.017 mm RMS over the
// skin for a 4 degree / 7 mm move in about 0.7 s on 2 cores.
struct RigidRegistrationOptions {
  std::optional<RegistrationBox> box;  // metric only inside it (fixed image mask); none = whole overlap
  int levels = 3;                      // 2x2x2 block-mean pyramid: voxels 4x, 2x, 1x the fixed CT's
  int histogram_bins = 32;             // Mattes joint histogram (elastix's usual 32; 50 was noisier)
  double sampling_fraction = 0.01;     // of the fixed voxels at full resolution (x4 and x16 on the
                                       // shrunk levels), kept where the mask holds more than air
  int max_iterations_per_level = 200;  // the finest level using all of them = did not converge
  double convergence = 1e-4;           // mm: full resolution stops when each of the last
  int convergence_window = 3;          // convergence_window steps moved the image by less than this
                                       // (also the shrunk levels' window for coarse_convergence)
  double coarse_convergence = 1e-3;    // shrunk levels stop when the metric's normalised slope over the
                                       // window falls below this (they only need to get close)
  bool regular_sampling = true;        // samples on a jittered regular grid (less noisy than random)
  uint32_t seed = 1;                   // which grid and jitter (a different seed: other samples, an
                                       // answer ~0.01-0.02 deg away on the cadaver head)
  double intensity_low = -1000;        // HU: both CTs are clamped to [low, high], the histograms'
  double intensity_high = 2000;        // fixed range (air below, bone and metal above)
  int threads = 0;                     // threads ITK may use (0 = one per core); the answer does not
                                       // depend on it (see "One answer" above)
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();  // moving_to_fixed guess
};

struct RigidRegistrationResult {
  Eigen::Isometry3d moving_to_fixed = Eigen::Isometry3d::Identity();
  double metric = 0;   // final Mattes mutual information, negated as ITK reports it (lower = better)
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
