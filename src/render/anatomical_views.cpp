#include "render/anatomical_views.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace maxillo::render {
namespace {

constexpr double kPerspectiveAngleDeg = 15;

// Unit vector from the focal point towards the camera.
Eigen::Vector3d towards_camera(StandardView view, const AnatomicalFrame& frame) {
  const Eigen::Vector3d right = -frame.left;  // the patient's right
  switch (view) {
    case StandardView::Frontal: return frame.anterior;
    case StandardView::Lateral: return right;
    case StandardView::Oblique: return (frame.anterior + right).normalized();
    case StandardView::LeftLateral: return frame.left;
  }
  return frame.anterior;
}

}  // namespace

std::string_view name_of(StandardView view) {
  switch (view) {
    case StandardView::Frontal: return "frontal";
    case StandardView::Lateral: return "lateral";
    case StandardView::Oblique: return "oblique";
    case StandardView::LeftLateral: return "left-lateral";
  }
  return "frontal";
}

std::optional<StandardView> parse_standard_view(std::string_view name) {
  for (auto view : {StandardView::Frontal, StandardView::Lateral, StandardView::Oblique, StandardView::LeftLateral})
    if (name == name_of(view)) return view;
  return std::nullopt;
}

Camera standard_camera(StandardView view, const AnatomicalFrame& frame, const Bounds& bounds, double aspect,
                       Projection projection) {
  assert(!bounds.empty() && "standard_camera: the scene has no vertices");
  assert(aspect > 0 && "standard_camera: aspect must be width / height > 0");
  const Eigen::Vector3d centre = bounds.centre();
  const Eigen::Vector3d back = towards_camera(view, frame);
  const Eigen::Vector3d up = (frame.superior - frame.superior.dot(back) * back).normalized();
  const Eigen::Vector3d image_right = (-back).cross(up);

  // Half extents of the bounds' projection on the image axes, and its depth radius.
  double half_width = 0, half_height = 0, radius = 0;
  for (int corner = 0; corner < 8; ++corner) {
    Eigen::Vector3d p((corner & 1) ? bounds.max.x() : bounds.min.x(), (corner & 2) ? bounds.max.y() : bounds.min.y(),
                      (corner & 4) ? bounds.max.z() : bounds.min.z());
    Eigen::Vector3d d = p - centre;
    half_width = std::max(half_width, std::abs(d.dot(image_right)));
    half_height = std::max(half_height, std::abs(d.dot(up)));
    radius = std::max(radius, d.norm());
  }
  const double half_view = std::max({half_height, half_width / aspect, 1e-3}) / (1 - 2 * kViewMargin);

  Camera camera;
  camera.focal_point = centre;
  camera.view_up = up;
  camera.projection = projection;
  camera.parallel_scale_mm = half_view;
  camera.view_angle_deg = kPerspectiveAngleDeg;
  const double half_angle = 0.5 * kPerspectiveAngleDeg * std::numbers::pi / 180;
  const double distance =
      projection == Projection::Parallel ? 2 * radius + 10 : half_view / std::tan(half_angle) + radius;
  camera.position = centre + distance * back;
  return camera;
}

}  // namespace maxillo::render
