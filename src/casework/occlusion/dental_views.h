#pragma once
// Pictures of a case's dental scans (issue 30), for the report's "Dental scans" section:
// - each arch's fit: the placed scan from the occlusal side (the upper arch seen from below, the
//   lower from above, the arch's front up), coloured by each point's distance to the CT's teeth
//   from 0 to 1 mm (the crowns dark, the gingiva or a cast's base light);
// - the augmented model: both jaws, the scanned crowns in blue and the CT's teeth in ivory, from
//   the front and the right.
#include <cstdint>
#include <filesystem>

#include "archive/archive.h"
#include "casework/occlusion/case_dental_scans.h"
#include "geometry/anatomical_frame.h"

namespace maxillo::casework {

void render_dental_fit(const TriangleMesh& placed, const TriangleMesh& ct_teeth, records::DentalArch arch,
                       const AnatomicalFrame& frame, const std::filesystem::path& png);

// Rendered and stored as "dental-render" pictures "augmented-frontal" and "augmented-lateral";
// nothing when no arch has an augmented dentition.
void store_augmented_pictures(Archive& archive, int64_t case_id, const CaseDentalRegistration& registered,
                              const AnatomicalFrame& frame);

}  // namespace maxillo::casework
