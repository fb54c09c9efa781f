// Analytic answers of the cephalometric measurements: constructed configurations with known
// angles and distances, invariance under rigid motions, image pixel orientation, and the
// mid-sagittal projection of 3D landmarks.
#include "core/angles.h"
#include "ceph/cephalometric_measures.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "ceph/cephalometric_analysis.h"
#include "ceph/sagittal_projection.h"
#include "core/error.h"

namespace maxillo::ceph {
namespace {

Eigen::Vector2d polar(double length, double degrees) {
  return length * Eigen::Vector2d(std::cos(degrees * kDeg), std::sin(degrees * kDeg));
}

// Sagittal frame (anterior, superior): N at the origin, S 70 mm behind it with SN rising 7 deg
// anteriorly, SNA 84, SNB 79 (ANB 5), occlusal line descending 8 deg anteriorly.
struct Configuration {
  Eigen::Vector2d S = polar(70, 180 + 7), N{0, 0};
  Eigen::Vector2d A = polar(58, 180 + 7 + 84), B = polar(95, 180 + 7 + 79);
  Eigen::Vector2d U6{-20, -62}, L6{-20, -64}, U1{10, -66}, L1{8, -68};
  Eigen::Vector2d ANS{8, -52}, PNS{-45, -55};
};

SagittalLandmarks as_set(const Configuration& c) {
  SagittalLandmarks set;
  set.points = {{"S", c.S},   {"N", c.N},   {"A", c.A},   {"B", c.B},     {"U6", c.U6},
                {"L6", c.L6}, {"U1", c.U1}, {"L1", c.L1}, {"ANS", c.ANS}, {"PNS", c.PNS}};
  return set;
}

TEST(CephalometricMeasures, AnglesOfAConstructedSkull) {
  Configuration c;
  EXPECT_NEAR(sna_deg(c.S, c.N, c.A), 84, 1e-9);
  EXPECT_NEAR(snb_deg(c.S, c.N, c.B), 79, 1e-9);
  EXPECT_NEAR(anb_deg(c.S, c.N, c.A, c.B), 5, 1e-9);
  // B in front of A seen from N: Class III, negative ANB.
  EXPECT_NEAR(anb_deg(c.S, c.N, c.A, polar(95, 180 + 7 + 86)), -2, 1e-9);
  EXPECT_NEAR(angle_at_deg({0, 0}, {1, 0}, {0, 3}), 90, 1e-12);
  EXPECT_NEAR(angle_at_deg({0, 0}, {1, 0}, {-1, 1e-9}), 180, 1e-6);
}

TEST(CephalometricMeasures, WitsOnAHorizontalAndATiltedOcclusalLine) {
  EXPECT_NEAR(wits_mm({5, 3}, {2, -4}, {0, 0}, {10, 0}), 3, 1e-12);   // AO 3 mm ahead: Class II
  EXPECT_NEAR(wits_mm({2, 3}, {6, -4}, {0, 0}, {10, 0}), -4, 1e-12);  // BO ahead: Class III
  // The same geometry rotated by 25 deg and moved: Wits does not change.
  Eigen::Rotation2Dd r(25 * kDeg);
  Eigen::Vector2d t(-3, 40);
  EXPECT_NEAR(wits_mm(r * Eigen::Vector2d(5, 3) + t, r * Eigen::Vector2d(2, -4) + t, t, r * Eigen::Vector2d(10, 0) + t),
              3, 1e-12);
}

TEST(CephalometricMeasures, NasionFrameAxesAndSigns) {
  Eigen::Vector2d S{-70, 0}, N{0, 0};  // SN horizontal
  auto frame = nasion_frame(S, N);
  // X: SN with its anterior end lowered by 6 deg; S ends up below the axis (inferior, +Y).
  Eigen::Vector2d s = in_nasion_frame(frame, S);
  EXPECT_NEAR(s.x(), -70 * std::cos(6 * kDeg), 1e-9);
  EXPECT_NEAR(s.y(), 70 * std::sin(6 * kDeg), 1e-9);
  // A point 10 mm anterior and 5 mm inferior in the frame.
  Eigen::Vector2d p = N + 10 * frame.x_axis + 5 * frame.y_axis;
  EXPECT_NEAR(in_nasion_frame(frame, p).x(), 10, 1e-12);
  EXPECT_NEAR(in_nasion_frame(frame, p).y(), 5, 1e-12);
  EXPECT_LT(frame.y_axis.y(), -0.99);  // Y points down (inferior)
  EXPECT_GT(frame.x_axis.x(), 0.99);   // X points forward
}

TEST(CephalometricMeasures, PalatalAngleAlphaIsNinetyWhenParallelToXAndGrowsWithUpwardRotation) {
  Eigen::Vector2d S{-70, 0}, N{0, 0};
  auto frame = nasion_frame(S, N);
  Eigen::Vector2d pns = N + -45 * frame.x_axis + 50 * frame.y_axis;
  Eigen::Vector2d ans_parallel = pns + 52 * frame.x_axis;
  EXPECT_NEAR(palatal_angle_alpha_deg(frame, ans_parallel, pns), 90, 1e-9);
  // ANS raised: the palatal plane rotates upward by 5 deg -> alpha 95 (positive change).
  Eigen::Vector2d ans_up = pns + 52 * std::cos(5 * kDeg) * frame.x_axis - 52 * std::sin(5 * kDeg) * frame.y_axis;
  EXPECT_NEAR(palatal_angle_alpha_deg(frame, ans_up, pns), 95, 1e-9);
}

TEST(CephalometricAnalysis, EveryMeasurementInvariantUnderRigidMotion) {
  Configuration c;
  auto reference = analyse(as_set(c));
  Eigen::Rotation2Dd r(-17 * kDeg);
  Eigen::Vector2d t(120, -35);
  SagittalLandmarks moved;
  for (const auto& [label, p] : as_set(c).points) moved.points[label] = r * p + t;
  auto analysis = analyse(moved);
  for (const auto& id : measurement_ids()) {
    auto expected = reference.value(id), actual = analysis.value(id);
    ASSERT_EQ(expected.has_value(), actual.has_value()) << id;
    if (expected) {
      EXPECT_NEAR(*actual, *expected, 1e-9) << id;
    }
  }
  EXPECT_NEAR(*analysis.value("ANB"), 5, 1e-9);
  EXPECT_FALSE(analysis.value("Si_X").has_value());
}

TEST(CephalometricAnalysis, ImagePixelsWithYDownGiveTheSameAnswer) {
  Configuration c;
  auto reference = analyse(as_set(c));
  // Pixels at 0.1 mm, y down, origin top-left, face to +x; and the same film mirrored (face to -x).
  LandmarkSet pixels, mirrored;
  for (const auto& [label, p] : as_set(c).points) {
    pixels.push_back({label, Eigen::Vector3d(1000 + p.x() * 10, 1200 - p.y() * 10, 0)});
    mirrored.push_back({label, Eigen::Vector3d(1000 - p.x() * 10, 1200 - p.y() * 10, 0)});
  }
  auto from_pixels = analyse(to_sagittal(pixels, LandmarkGeometry::kAuto, {0.1, ImageVerticalAxis::kDown}, "pixels"));
  auto from_mirrored =
      analyse(cephalogram_to_sagittal(mirrored, {0.1, ImageVerticalAxis::kDown, FacingDirection::kMinusX}));
  for (const auto& id : measurement_ids()) {
    if (!reference.value(id)) continue;
    EXPECT_NEAR(*from_pixels.value(id), *reference.value(id), 1e-9) << id;
    EXPECT_NEAR(*from_mirrored.value(id), *reference.value(id), 1e-9) << id;
  }
  // Reading y as pointing up would turn the face upside down: alpha and the frame coordinates
  // change sign pattern, so the orientation matters.
  auto wrong = analyse(to_sagittal(pixels, LandmarkGeometry::kCephalogram, {0.1, ImageVerticalAxis::kUp}, "pixels"));
  EXPECT_GT(std::abs(*wrong.value("ANS_Y") - *reference.value("ANS_Y")), 10);
}

TEST(CephalometricAnalysis, MissingLandmarksMakeOnlyTheirMeasurementsUnavailable) {
  Configuration c;
  auto set = as_set(c);
  set.points.erase("B");
  set.points.erase("U6");
  auto analysis = analyse(set);
  EXPECT_NEAR(*analysis.value("SNA"), 84, 1e-9);
  for (const char* id : {"SNB", "ANB", "Wits"}) {
    ASSERT_NE(analysis.find(id), nullptr);
    EXPECT_FALSE(analysis.value(id).has_value()) << id;
    EXPECT_NE(analysis.find(id)->not_available_reason.find("B"), std::string::npos) << id;
  }
  set.points["B"] = c.B;
  auto no_molar = analyse(set);
  EXPECT_NE(no_molar.find("Wits")->not_available_reason.find("U6"), std::string::npos);
  EXPECT_TRUE(no_molar.value("alpha").has_value());
  EXPECT_NE(no_molar.find("Si_Y")->not_available_reason.find("Si"), std::string::npos);
}

TEST(CephalometricAnalysis, WitsUsesTheFunctionalOcclusalPlaneWhenPremolarsArePresent) {
  // Occlusal line horizontal through the molar and premolar midpoints; incisors off the line.
  SagittalLandmarks set;
  set.points = {{"A", {10, 5}}, {"B", {7, -30}}, {"U6", {-20, 1}}, {"L6", {-20, -1}},
                {"U4", {0, 1}}, {"L4", {0, -1}}, {"U1", {15, 10}}, {"L1", {12, -9}}};
  auto functional = analyse(set);
  EXPECT_NEAR(*functional.value("Wits"), 3, 1e-12);
  EXPECT_NE(functional.find("Wits")->note.find("functional"), std::string::npos);
  set.points.erase("U4");
  auto incisal = analyse(set);
  EXPECT_NE(incisal.find("Wits")->note.find("incisor"), std::string::npos);
}

TEST(CephalometricNorms, DeviationFlags) {
  Norm sna = *norm_for("SNA", Sex::kUnknown);
  EXPECT_EQ(deviation_of(82, sna), Deviation::kWithinOneSd);
  EXPECT_EQ(deviation_of(86, sna), Deviation::kBeyondOneSd);
  EXPECT_EQ(deviation_of(74, sna), Deviation::kBeyondTwoSd);
  EXPECT_DOUBLE_EQ(norm_for("Wits", Sex::kMale)->mean, -1);
  EXPECT_DOUBLE_EQ(norm_for("Wits", Sex::kFemale)->mean, 0);
  EXPECT_FALSE(norm_for("ANS_X", Sex::kUnknown).has_value());
}

// 3D: the constructed skull placed in a tilted, shifted mid-sagittal plane of LPS space, with
// bilateral molars symmetric about it; the projection recovers every 2D measurement.
TEST(SagittalProjection, RecoversTheMidSagittalConfigurationFromThreeDimensions) {
  Configuration c;
  auto reference = analyse(as_set(c));
  // Sagittal (anterior a, superior s) -> LPS (0, -a, s), then a rotation about z (yaw) and y (roll).
  Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(12 * kDeg, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-7 * kDeg, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  Eigen::Vector3d shift(4, 10, -30);
  auto lps = [&](const Eigen::Vector2d& p, double lateral) {
    return Eigen::Vector3d(rotation * Eigen::Vector3d(lateral, -p.x(), p.y()) + shift);
  };
  LandmarkSet set;
  for (const auto& [label, p] : as_set(c).points) {
    if (label == "U6" || label == "L6") {
      set.push_back({label + "R", lps(p, -25)});
      set.push_back({label + "L", lps(p, 25)});
    } else {
      set.push_back({label, lps(p, 0)});
    }
  }
  auto projection = project_to_mid_sagittal(set);
  ASSERT_EQ(projection.status, ProjectionStatus::kOk);
  EXPECT_NEAR(projection.rms_distance_mm, 0, 1e-9);
  EXPECT_NEAR(projection.normal.dot(rotation * Eigen::Vector3d::UnitX()), 1, 1e-9);
  auto analysis = analyse(projection.landmarks);
  for (const auto& id : measurement_ids()) {
    if (!reference.value(id)) continue;
    EXPECT_NEAR(*analysis.value(id), *reference.value(id), 1e-9) << id;
  }
}

TEST(SagittalProjection, RefusesTooFewOrCollinearMidlinePoints) {
  LandmarkSet two = {{"S", {0, 0, 20}}, {"N", {0, -70, 28}}};
  EXPECT_EQ(project_to_mid_sagittal(two).status, ProjectionStatus::kTooFewMidlinePoints);
  LandmarkSet collinear = {{"S", {0, 0, 0}}, {"N", {0, -70, 0}}, {"A", {0, -60, 0}}};
  EXPECT_EQ(project_to_mid_sagittal(collinear).status, ProjectionStatus::kDegenerate);
  EXPECT_THROW(to_sagittal(two, LandmarkGeometry::kVolumeLps, {}, "two.csv"), Error);
}

}  // namespace
}  // namespace maxillo::ceph
