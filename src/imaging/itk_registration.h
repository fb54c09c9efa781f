#pragma once
// Internal to src/imaging: ITK's rigid mutual-information registration on plain buffers, for
// rigid_registration.cpp. Like itk_filters.h this header (and itk_registration.cpp) knows no
// Eigen: ITK 5.2 bundles an Eigen 3.3 whose include guards collide with the system Eigen 3.4.
//
// Transforms here follow ITK's convention: they map a point of the FIXED image's physical
// space (LPS mm) to the MOVING image's (fixed -> moving), as p_moving = matrix * (p - centre)
// + centre + translation.
#include <array>
#include <cstdint>
#include <vector>

#include "imaging/itk_filters.h"

namespace maxillo::itk_registration {

struct Image {
  itk_filters::Grid grid;
  std::array<double, 3> origin{};
  std::array<double, 9> direction{};  // row-major 3x3, columns = axes of i, j, k
  const int16_t* hu = nullptr;        // grid voxels, x fastest
};

struct RigidMap {
  std::array<double, 9> matrix{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major rotation
  std::array<double, 3> translation{};
  std::array<double, 3> centre{};
};

struct Settings {
  int levels = 3;                  // pyramid of 2x2x2 block means: 2^(levels-1) ... 1
  int histogram_bins = 32;
  double sampling_fraction = 0.01; // of the full-resolution voxels; f^2 times that on a level shrunk by f
  int max_iterations_per_level = 200;
  double fine_convergence = 1e-6;   // full resolution: stop when the metric's normalised slope over
  int fine_window = 6;              // the last fine_window iterations falls below this
  double coarse_convergence = 1e-3; // the same on the shrunk levels (they only need to get close)
  bool regular_sampling = true;     // samples on a jittered regular grid instead of at random
  uint32_t seed = 1;
  int threads = 0;  // 0 = ITK's default
  const itk_filters::Mask* fixed_mask = nullptr;  // on the fixed grid; null = whole image
  RigidMap initial;                                // fixed -> moving
};

struct Outcome {
  RigidMap fixed_to_moving;
  double metric = 0;  // Mattes mutual information, negated (lower is better)
  int iterations = 0;  // over all levels
  int last_level_iterations = 0;  // on the finest level (== the limit: not converged)
};

// Throws maxillo::Error(kProcessing, "registration", reason) when ITK fails.
Outcome register_rigid(const Image& fixed, const Image& moving, const Settings& settings);

}  // namespace maxillo::itk_registration
