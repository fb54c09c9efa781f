#pragma once
// Pictures of a validation (thesis ch. 8, Figs. of error maps and profiles): the signed distance from the predicted
// to the post-operative skin as a colour map on the predicted face, and the mid-sagittal profiles of the
// pre-operative, predicted and post-operative faces overlaid.
#include <filesystem>
#include <vector>

#include "ceph/landmark.h"
#include "core/triangle_mesh.h"
#include "render/anatomical_views.h"

namespace maxillo::casework {

// error-map-{frontal,lateral,oblique}.png in `folder`: the face region coloured blue (prediction behind the real
// face) - white - red (in front) over -range..+range mm with a colour bar, the rest of the skin plain. `distance_mm`
// has one value per vertex, NaN outside the region.
std::vector<std::filesystem::path> render_error_maps(const TriangleMesh& predicted,
                                                     const std::vector<double>& distance_mm,
                                                     const AnatomicalFrame& frame, double range_mm,
                                                     const std::filesystem::path& folder);

// The three skins cut by the mid-sagittal plane (through subnasale, normal to the frame's left axis), the facial part
// of each profile (from above nasion to below the chin, the front of the head) drawn to scale: anterior to the right,
// superior up, millimetres from subnasale.
void write_profile_overlay(const TriangleMesh& preop, const TriangleMesh& predicted, const TriangleMesh& actual,
                           const LandmarkSet& landmarks, const AnatomicalFrame& frame,
                           const std::filesystem::path& png);

}  // namespace maxillo::casework
