#pragma once
// The "occlusion" section of the consultation report (issue 6 item 7): the occlusionogram
// image, contacts per tooth, the final occlusion's transform in the anatomical frame, and the
// surgical splint's figures with a render of it. Built from an OcclusionRun (occlusion_run.h).
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>

#include "archive/archive.h"
#include "casework/occlusion_run.h"
#include "render/anatomical_views.h"
#include "report/report_model.h"

namespace maxillo::sections {

// A rigid motion read in the anatomical frame: the displacement of `reference` (mm along
// anterior, superior, left) and the rotation vector's components (degrees): pitch positive when
// the front goes up (about the patient's right-to-left axis, i.e. minus the component along
// `left`, since anterior x left = superior), roll positive when the left side goes up (along
// `anterior`), yaw positive when the front turns to the patient's left (along `superior`).
// The components are exact for a rotation about one of the axes and the usual reading of small
// rotations; they do not depend on an Euler-angle order.
struct AnatomicalMotion {
  double anterior_mm = 0, superior_mm = 0, left_mm = 0;
  double pitch_deg = 0, roll_deg = 0, yaw_deg = 0;
};
AnatomicalMotion anatomical_motion(const Eigen::Isometry3d& motion, const AnatomicalFrame& frame,
                                   const Eigen::Vector3d& reference);

// The section. `splint_png` (may be empty) is a render of the splint shown beside the
// occlusionogram (render_splint below). The upper arch's motion (from the start pose to the
// final one) is read at the upper arch's centroid at the start.
report::Section occlusion_section(const casework::OcclusionRun& run, const AnatomicalFrame& frame,
                                  const std::filesystem::path& splint_png = {});

// The run's splint over its lower arch, seen obliquely from the front, into `png`.
void render_splint(const casework::OcclusionRun& run, const AnatomicalFrame& frame, const std::filesystem::path& png);

// Stores occlusion.json, occlusionogram.png and splint.stl (when made) of the run's folder as
// artefacts of the case ("occlusion", "occlusionogram", "splint"), keyed by their inputs.
void store_occlusion_artefacts(Archive& archive, int64_t case_id, const casework::OcclusionRun& run,
                               const std::vector<std::string>& input_hashes);

}  // namespace maxillo::sections
