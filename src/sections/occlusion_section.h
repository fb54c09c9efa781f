#pragma once
// The "occlusion" section of the consultation report (issue 6 item 7): the occlusionogram
// image, contacts per tooth, the final occlusion's transform in the anatomical frame, and the
// surgical splint's figures with a render of it. Built from the case's stored occlusion.
#include <Eigen/Geometry>

#include "records/occlusion_archive.h"
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

// The section of a stored occlusion (records/occlusion_archive.h): the occlusionogram and the
// splint's render, the alignment's facts, contacts per tooth, the upper arch's motion (from the
// scanned position and from the start pose, read at its centroid) and the splint's figures.
report::Section occlusion_section(const records::StoredOcclusion& occlusion, const AnatomicalFrame& frame);

}  // namespace maxillo::sections
