#pragma once
// An occlusion run kept with its case: its splint rendered over the lower arch in the case's
// anatomical frame, and the run's outputs stored (records/occlusion_archive.h) under a key of
// its inputs, where the consultation report finds them.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "casework/occlusion/occlusion_run.h"
#include "geometry/anatomical_frame.h"

namespace maxillo::casework {

// `input_hashes`: of the arches' and the pairs' files (empty for the phantom's own arches); the
// key adds the start pose, the contact threshold and whether a splint was made. The render is
// written into the run's folder as splint.png.
void store_occlusion_run(Archive& archive, int64_t case_id, const OcclusionRun& run,
                         const std::vector<std::string>& input_hashes, const AnatomicalFrame& frame);

// The run's splint over its lower arch, seen obliquely from the front, into `png`.
void render_splint(const OcclusionRun& run, const AnatomicalFrame& frame, const std::filesystem::path& png);

}  // namespace maxillo::casework
