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

using Samples = std::vector<std::array<double, 3>>;  // LPS mm, in the order the metric sums them

struct Settings {
  std::vector<Samples> samples;  // per pyramid level, [0] = full resolution; their number = the levels
  int histogram_bins = 32;
  double low = -1000, high = 2000;  // both CTs clamped to [low, high], the histograms' range
  int max_iterations_per_level = 200;
  double fine_step_mm = 1e-4;        // full resolution: stop when `window` steps in a row each moved the
                                     // fixed domain's corners by less than this
  double coarse_convergence = 1e-3;  // shrunk levels (they only need to get close): stop when the metric's
  int window = 3;                    // normalised slope over the last `window` iterations falls below this
  int threads = 0;                   // 0 = ITK's default; the answer does not depend on it
  RigidMap initial;                  // fixed -> moving
};

struct Outcome {
  RigidMap fixed_to_moving;
  double metric = 0;      // Mattes mutual information, negated (lower is better)
  int iterations = 0;     // over all levels
  bool converged = true;  // false: the finest level stopped at max_iterations_per_level
};

// Throws maxillo::Error(kProcessing, "registration", reason) when ITK fails.
Outcome register_rigid(const Image& fixed, const Image& moving, const Settings& settings);

}  // namespace maxillo::itk_registration
