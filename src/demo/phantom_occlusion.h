#pragma once
// The demo's virtual occlusion on the synthetic phantom (no real data needed): the upper and
// lower teeth (Tissue::kUpperTooth, kLowerTooth) are extracted as surfaces from the phantom's
// labels, the phantom's own occlusion is the reference, the upper arch is started from a
// displaced pose and brought back by guided alignment with 4 spring pairs taken where the teeth
// touch; the occlusionogram and the splint follow (occlusion_run.h).
#include <cstdint>
#include <filesystem>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "casework/occlusion_run.h"
#include "sample/phantom.h"

namespace maxillo::demo {

struct PhantomArches {
  TriangleMesh upper, lower;  // LPS mm, the phantom's frame (in occlusion as they are)
};

// Surfaces of the two tooth labels (every tooth kept, as separate closed shells).
PhantomArches phantom_arches(const Phantom& phantom);

// The displaced start of the demo: 2 degrees about an oblique axis through the upper arch's
// centroid and (0.8, -1.0, 1.5) mm. Deterministic.
Eigen::Isometry3d phantom_start_pose(const TriangleMesh& upper);

// The occlusion of `arches` from phantom_start_pose, lowered into contact: computed, nothing
// written (casework::compute_occlusion).
casework::OcclusionRun compute_phantom_occlusion(const PhantomArches& arches);

// The same for the phantom of `skeletal_class` (1 mm). It renders nothing, so the demo runs it
// beside the CT's reception.
casework::OcclusionRun compute_phantom_occlusion(SkeletalClass skeletal_class);

// A computed phantom occlusion written into `folder` and stored with the case with a render of
// the splint (anatomical frame from `landmarks`), where the consultation report finds it.
void archive_phantom_occlusion(Archive& archive, int64_t case_id, casework::OcclusionRun run,
                               const LandmarkSet& landmarks, const std::filesystem::path& folder);

}  // namespace maxillo::demo
