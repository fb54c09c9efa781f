#pragma once
// The labelled CT of a case as planning and soft tissue prediction need it, computed once and
// shared by `plan apply` and `simulate`: the CT segmentation (imaging/segmentation.h) with the
// sinus air taken from the CT's closed air cavities (planning/enclosed_air.h says why), and the
// same in the phantom's labels with the jaws told apart (planning/jaw_separation.h).
#include <cstdint>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "core/volume.h"

namespace maxillo::pipeline {

struct CaseTissues {
  LabelVolume segmentation;  // 0 background, 1 soft tissue, 2 enclosed air (sinus), 3 bone, 4 teeth
  LabelVolume jaws;          // phantom Tissue values: upper/lower teeth, mandible apart
};

// The case's primary CT series, segmented. Throws what volume loading and jaw separation throw.
CaseTissues load_case_tissues(Archive& archive, int64_t case_id, const LandmarkSet& landmarks);
// The same for a CT already in memory.
CaseTissues segment_case_tissues(const Volume& ct, const LandmarkSet& landmarks);

}  // namespace maxillo::pipeline
