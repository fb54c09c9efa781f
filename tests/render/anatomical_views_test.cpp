#include "render/anatomical_views.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace maxillo::render {
namespace {

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_LT((actual - expected).norm(), tolerance)
      << "actual " << actual.transpose() << " expected " << expected.transpose();
}

TEST(StandardView, NamesRoundTripAndUnknownIsRejected) {
  for (auto view : {StandardView::Frontal, StandardView::Lateral, StandardView::Oblique})
    EXPECT_EQ(parse_standard_view(name_of(view)), view);
  EXPECT_FALSE(parse_standard_view("Lateral"));
  EXPECT_FALSE(parse_standard_view("top"));
}

class StandardCameraTest : public ::testing::Test {
 protected:
  AnatomicalFrame frame_;                           // patient axes
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
