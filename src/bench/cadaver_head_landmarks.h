#pragma once
// Landmarks of the cadaver head (read_cadaver_head's LPS mm), placed by hand on its mid-sagittal
// and axial slices to within a few mm: what the detector cannot find there stands in for it in
// the benchmarks on real data. The scan has 2 mm slices and amalgam streaks across the teeth, so
// the first molars are not found automatically (issue 28); the midline lies at x = -21.5.
// tests/e2e/cadaver_simulate_test.cpp holds the same points as a CSV: it is a black-box test of
// the program and links none of its libraries.
#include <string>
#include <vector>

#include "ceph/landmark.h"

namespace maxillo::bench {

LandmarkSet cadaver_head_landmarks_by_hand();

// `detected` with every hand-placed landmark it lacks added; `added` lists their labels.
LandmarkSet completed_by_hand(const LandmarkSet& detected, std::vector<std::string>& added);

}  // namespace maxillo::bench
