#pragma once
// Where to put the camera for the standard clinical views, in the patient's anatomical frame
// (geometry/anatomical_frame.h). Pure Eigen, no VTK.
//
// Views (each looks at the scene centre, superior axis up in the image):
//   Frontal : camera in front of the face; the patient's left is on the image's right.
//   Lateral : right profile, the orthodontic standard: camera on the patient's right, the face
//             pointing to the image's right.
//   Oblique : 45 degrees between frontal and right lateral (right-front).
//   LeftLateral : left profile, the face pointing to the image's left (what the right lateral
//             hides: the left-sided landmarks).
#include <Eigen/Core>
#include <optional>
#include <string_view>

#include "geometry/anatomical_frame.h"
#include "render/scene.h"

namespace maxillo::render {

enum class StandardView { Frontal, Lateral, Oblique, LeftLateral };

std::string_view name_of(StandardView view);  // "frontal", "lateral", "oblique", "left-lateral"
std::optional<StandardView> parse_standard_view(std::string_view name);  // inverse of name_of

// Fraction of the image left free around the scene's projection on each side.
inline constexpr double kViewMargin = 0.06;

// A camera for `view` that looks at bounds.centre() with frame.superior up and fits the
// projection of the bounds' 8 corners into an image of aspect = width / height, with
// kViewMargin to spare. Perspective uses a 15 degree view angle. bounds must not be empty.
Camera standard_camera(StandardView view, const AnatomicalFrame& frame, const Bounds& bounds, double aspect,
                       Projection projection = Projection::Parallel);

}  // namespace maxillo::render
