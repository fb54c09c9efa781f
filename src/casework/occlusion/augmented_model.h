#pragma once
// The augmented model of a case (issue 30): each jaw's CT teeth with their crowns replaced by the
// scanned ones (dental/augmented_dentition.h), as a closed surface the occlusion, the splints and
// the renders can use: the zero level of the dentition's field, which puts the crowns where the
// scan is, to a fraction of the grid's voxel.
#include <cstdint>
#include <vector>

#include "casework/surfaces/case_tissues.h"
#include "core/triangle_mesh.h"
#include "dental/augmented_dentition.h"
#include "records/dental_scans.h"

namespace maxillo::casework {

struct AugmentedArch {
  records::DentalArch arch = records::DentalArch::kUpper;
  TriangleMesh surface;  // closed, LPS mm
  int64_t crown_voxels = 0, ct_voxels_kept = 0, ct_voxels_cut = 0;
};

struct AugmentedModelOptions {
  dental::AugmentedDentitionOptions dentition;
};

// `ct` in HU; `tissues.jaws` tell the jaws' teeth apart; `ct_teeth` is this arch's jaw's teeth
// surface and `opposing_teeth` the other jaw's (they give the occlusal direction); `placed_scan`
// the arch's scan in the CT's frame.
AugmentedArch augmented_arch(const Volume& ct, const CaseTissues& tissues, records::DentalArch arch,
                             const TriangleMesh& ct_teeth, const TriangleMesh& opposing_teeth,
                             const TriangleMesh& placed_scan, const AugmentedModelOptions& options = {});

}  // namespace maxillo::casework
