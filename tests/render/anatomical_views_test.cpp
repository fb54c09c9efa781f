#include "render/anatomical_views.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace maxillo::render {
namespace {

// Porions and orbitales of an average adult head in a frame where anterior = -y,
// superior = +z, left = +x (mm).
LandmarkSet canonical_landmarks() {
  return {{"PoR", {-60, 10, 0}}, {"PoL", {60, 10, 0}}, {"OrR", {-33, -70, 0}}, {"OrL", {33, -70, 0}},
          {"N", {0, -90, 25}}, {"S", {0, -20, 20}}};
}

LandmarkSet transformed(const LandmarkSet& set, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift) {
  LandmarkSet out = set;
  for (auto& landmark : out) landmark.position = rotation * landmark.position + shift;
  return out;
}

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_LT((actual - expected).norm(), tolerance) << "actual " << actual.transpose() << " expected "
                                                   << expected.transpose();
}

TEST(AnatomicalFrame, WithoutLandmarksUsesPatientAxes) {
  auto frame = anatomical_frame({});
  EXPECT_EQ(frame.source, FrameSource::PatientAxes);
  expect_near(frame.anterior, {0, -1, 0}, 1e-12);
  expect_near(frame.superior, {0, 0, 1}, 1e-12);
  expect_near(frame.left, {1, 0, 0}, 1e-12);
}

TEST(AnatomicalFrame, FrankfortFrameFollowsARotatedHead) {
  // Head pitched 20 degrees chin-down and turned 30 degrees, then moved.
  Eigen::Matrix3d rotation = (Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitX()) *
                              Eigen::AngleAxisd(0.52, Eigen::Vector3d::UnitZ())).toRotationMatrix();
  Eigen::Vector3d shift(12, -150, 300);
  auto frame = anatomical_frame(transformed(canonical_landmarks(), rotation, shift));
  EXPECT_EQ(frame.source, FrameSource::Frankfort);
  expect_near(frame.anterior, rotation * Eigen::Vector3d(0, -1, 0), 1e-9);
  expect_near(frame.superior, rotation * Eigen::Vector3d(0, 0, 1), 1e-9);
  expect_near(frame.left, rotation * Eigen::Vector3d(1, 0, 0), 1e-9);
  expect_near(frame.origin, rotation * Eigen::Vector3d(0, 10, 0) + shift, 1e-9);
  EXPECT_NEAR(frame.anterior.cross(frame.left).dot(frame.superior), 1.0, 1e-12);  // right-handed
}

TEST(AnatomicalFrame, OneOrbitaleIsEnoughAndFrameStaysOrthonormal) {
  LandmarkSet set = {{"PoR", {-60, 10, 3}}, {"PoL", {60, 12, -2}}, {"OrL", {33, -70, 1}}};
  auto frame = anatomical_frame(set);
  ASSERT_EQ(frame.source, FrameSource::Frankfort);
  EXPECT_NEAR(frame.anterior.norm(), 1, 1e-12);
  EXPECT_NEAR(frame.anterior.dot(frame.left), 0, 1e-12);
  EXPECT_NEAR(frame.superior.dot(frame.left), 0, 1e-12);
  EXPECT_GT(frame.anterior.dot(Eigen::Vector3d(0, -1, 0)), 0.99);
}

TEST(AnatomicalFrame, DegenerateLandmarksFallBack) {
  // Porions 5 mm apart: no reliable transverse axis.
  EXPECT_EQ(anatomical_frame({{"PoR", {-2, 0, 0}}, {"PoL", {3, 0, 0}}, {"OrR", {0, -70, 0}}}).source,
            FrameSource::PatientAxes);
  // Orbitale on the porion axis: no forward direction.
  EXPECT_EQ(anatomical_frame({{"PoR", {-60, 0, 0}}, {"PoL", {60, 0, 0}}, {"OrR", {30, 0, 0}}}).source,
            FrameSource::PatientAxes);
  // Missing orbitales.
  EXPECT_EQ(anatomical_frame({{"PoR", {-60, 0, 0}}, {"PoL", {60, 0, 0}}}).source, FrameSource::PatientAxes);
}

TEST(StandardView, NamesRoundTripAndUnknownIsRejected) {
  for (auto view : {StandardView::Frontal, StandardView::Lateral, StandardView::Oblique})
    EXPECT_EQ(parse_standard_view(name_of(view)), view);
  EXPECT_FALSE(parse_standard_view("Lateral"));
  EXPECT_FALSE(parse_standard_view("top"));
}

class StandardCameraTest : public ::testing::Test {
 protected:
  AnatomicalFrame frame_;  // patient axes
  Bounds bounds_{{-40, -100, -30}, {40, 100, 50}};  // 80 wide, 200 deep, 80 high
  Eigen::Vector3d direction(const Camera& c) { return (c.focal_point - c.position).normalized(); }
  Eigen::Vector3d image_right(const Camera& c) { return direction(c).cross(c.view_up); }
};

TEST_F(StandardCameraTest, FrontalLooksBackwardsWithPatientLeftOnImageRight) {
  auto camera = standard_camera(StandardView::Frontal, frame_, bounds_, 1.0);
  expect_near(camera.focal_point, {0, 0, 10}, 1e-12);
  expect_near(direction(camera), {0, 1, 0}, 1e-12);
  expect_near(camera.view_up, {0, 0, 1}, 1e-12);
  expect_near(image_right(camera), frame_.left, 1e-12);
  // Half height 40 mm fits, widened by the margins.
  EXPECT_NEAR(camera.parallel_scale_mm, 40 / (1 - 2 * kViewMargin), 1e-9);
}

TEST_F(StandardCameraTest, LateralIsARightProfileFacingImageRight) {
  auto camera = standard_camera(StandardView::Lateral, frame_, bounds_, 1.0);
  expect_near(direction(camera), frame_.left, 1e-12);  // camera on the patient's right
  expect_near(image_right(camera), frame_.anterior, 1e-12);
  EXPECT_NEAR(camera.parallel_scale_mm, 100 / (1 - 2 * kViewMargin), 1e-9);  // 200 mm deep
  // A wide image needs less height to fit the same depth.
  EXPECT_NEAR(standard_camera(StandardView::Lateral, frame_, bounds_, 2.0).parallel_scale_mm,
              50 / (1 - 2 * kViewMargin), 1e-9);
}

TEST_F(StandardCameraTest, ObliqueIsBetweenFrontalAndRightLateral) {
  auto camera = standard_camera(StandardView::Oblique, frame_, bounds_, 1.0);
  Eigen::Vector3d back = -direction(camera);
  EXPECT_NEAR(back.dot(frame_.anterior), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(back.dot(-frame_.left), std::sqrt(0.5), 1e-12);
}

TEST_F(StandardCameraTest, PerspectiveCameraSeesTheWholeBox) {
  auto camera = standard_camera(StandardView::Frontal, frame_, bounds_, 1.0, Projection::Perspective);
  const double distance = (camera.position - camera.focal_point).norm();
  const double half_angle = camera.view_angle_deg / 2 * std::numbers::pi / 180;
  // The nearest face of the box (y = -100) must fit vertically at its depth.
  const double nearest = distance - 100;
  EXPECT_GT(nearest * std::tan(half_angle), 40.0);
}

}  // namespace
}  // namespace maxillo::render
