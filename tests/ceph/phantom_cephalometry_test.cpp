// Known answers on the synthetic phantom: its landmarks (3D, LPS) through the mid-sagittal
// projection and the analysis give the design's angles; the nasion-frame coordinates and alpha
// match values computed from the design constants (SN 7 deg above Frankfort, so the X axis lies
// 1 deg above Frankfort).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "ceph/cephalometric_analysis.h"
#include "ceph/cephalometric_measures.h"
#include "sample/phantom.h"
#include "sample/phantom_design.h"

namespace maxillo::ceph {
namespace {

PhantomSpec coarse(SkeletalClass c) {
  PhantomSpec spec = phantom_spec_for_class(c);
  spec.spacing_mm = 4;  // landmarks are analytic: the grid does not matter
  return spec;
}

CephalometricAnalysis analyse_phantom(const PhantomSpec& spec) {
  auto phantom = make_phantom(spec);
  return analyse(to_sagittal(phantom.landmarks, LandmarkGeometry::kAuto, {}, "phantom"));
}

// (anterior, superior) of an LPS point of the phantom's mid-sagittal plane x = 0.
Eigen::Vector2d sagittal(const Eigen::Vector3d& p) { return {-p.y(), p.z()}; }

TEST(PhantomCephalometry, DefaultPhantomHasTheDesignAngles) {
  auto analysis = analyse_phantom(coarse(SkeletalClass::I));
  EXPECT_NEAR(*analysis.value("SNA"), 82, 0.05);
  EXPECT_NEAR(*analysis.value("SNB"), 80, 0.05);
  EXPECT_NEAR(*analysis.value("ANB"), 2, 0.05);
  EXPECT_EQ(analysis.find("SNA")->deviation, Deviation::kWithinOneSd);
  EXPECT_NE(analysis.frame.find("mid-sagittal"), std::string::npos);
}

TEST(PhantomCephalometry, NasionFrameAndAlphaFromTheDesignConstants) {
  auto spec = coarse(SkeletalClass::I);
  auto design = sample::make_design(spec);
  auto analysis = analyse_phantom(spec);
  // X axis: 1 deg above Frankfort (z = 0), anterior; Y: perpendicular, inferior.
  double rise = (sample::kSnToFrankfort - kNasionFrameRotationDeg) * kDeg;
  Eigen::Vector2d x_axis(std::cos(rise), std::sin(rise)), y_axis(std::sin(rise), -std::cos(rise));
  Eigen::Vector2d n = sagittal(design.N);
  for (auto [label, point] : {std::pair{"ANS", design.ANS}, std::pair{"PNS", design.PNS}}) {
    Eigen::Vector2d d = sagittal(point) - n;
    EXPECT_NEAR(*analysis.value(std::string(label) + "_X"), d.dot(x_axis), 1e-6) << label;
    EXPECT_NEAR(*analysis.value(std::string(label) + "_Y"), d.dot(y_axis), 1e-6) << label;
  }
  Eigen::Vector2d palatal = sagittal(design.ANS) - sagittal(design.PNS);
  double palatal_rise_deg = std::atan2(palatal.y(), palatal.x()) / kDeg;
  EXPECT_NEAR(*analysis.value("alpha"), 90 + palatal_rise_deg - 1, 1e-6);
}

TEST(PhantomCephalometry, WitsFollowsTheSkeletalClass) {
  auto class1 = analyse_phantom(coarse(SkeletalClass::I));
  auto class2 = analyse_phantom(coarse(SkeletalClass::II));
  auto class3 = analyse_phantom(coarse(SkeletalClass::III));
  // Design: A and B projected on the design occlusal plane (descending 8 deg anteriorly).
  auto design = sample::make_design(coarse(SkeletalClass::I));
  double tilt = sample::kOcclusalTilt * kDeg;
  Eigen::Vector2d occlusal_anterior(std::cos(tilt), -std::sin(tilt));
  double design_wits = (sagittal(design.A) - sagittal(design.B)).dot(occlusal_anterior);
  EXPECT_NEAR(*class1.value("Wits"), design_wits, 0.5) << class1.find("Wits")->note;
  EXPECT_GT(*class2.value("ANB"), 4);
  EXPECT_LT(*class3.value("ANB"), -1);
  // The mandible 5 mm back (Class II) moves BO about 5 mm back along the occlusal line.
  EXPECT_NEAR(*class2.value("Wits") - *class1.value("Wits"), 5 * std::cos(tilt), 1.0);
  EXPECT_LT(*class3.value("Wits"), *class1.value("Wits") - 5);
}

}  // namespace
}  // namespace maxillo::ceph
