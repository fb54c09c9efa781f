#pragma once
// The demo's virtual occlusion on the phantom's augmented model (issue 30: the scanned crowns
// on the CT's roots, in the CT's frame; casework/occlusion/augmented_model.h): the registered occlusion is
// the reference, the upper arch is started from a displaced pose and brought back by guided
// alignment with 4 spring pairs taken where the teeth touch; the occlusionogram and the splint
// follow (occlusion_run.h), in the CT's frame.
#include <cstdint>
#include <filesystem>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "casework/occlusion/case_dental_scans.h"
#include "casework/occlusion/occlusion_run.h"
#include "sample/phantom.h"

namespace maxillo::demo {

struct PhantomArches {
  TriangleMesh upper, lower;  // LPS mm, the phantom's frame (in occlusion as they are)
};

// The augmented model's two jaws (casework/occlusion/augmented_model.h), in the CT's frame. Error naming
// the missing jaw when the registration did not make both.
PhantomArches augmented_arches(const casework::CaseDentalRegistration& dental);
// The same from a computed registration job (casework::compute_dental_registration), before it is stored.
PhantomArches augmented_arches(const casework::DentalRegistrationJob& job);

// The displaced start of the demo: 2 degrees about an oblique axis through the upper arch's
// centroid and (0.8, -1.0, 1.5) mm. Deterministic.
Eigen::Isometry3d phantom_start_pose(const TriangleMesh& upper);

// The occlusion of `arches` from phantom_start_pose, lowered into contact: computed, nothing
// written (casework::compute_occlusion).
casework::OcclusionRun compute_phantom_occlusion(const PhantomArches& arches);

// A computed phantom occlusion written into `folder` and stored with the case with a render of
// the splint (anatomical frame from `landmarks`), where the consultation report finds it.
void archive_phantom_occlusion(Archive& archive, int64_t case_id, casework::OcclusionRun run,
                               const LandmarkSet& landmarks, const std::filesystem::path& folder);

}  // namespace maxillo::demo
