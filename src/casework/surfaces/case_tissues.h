#pragma once
// The labelled CT of a case as planning and soft tissue prediction need it, computed once and
// shared by `plan apply` and `simulate`: the CT segmentation (imaging/segmentation.h) with the
// sinus air taken from the CT's closed air cavities (planning/enclosed_air.h says why), and the
// same in the phantom's labels with the jaws told apart (planning/jaw_separation.h).
#include <cstdint>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "core/volume.h"
#include "imaging/segmentation.h"

namespace maxillo::casework {

struct CaseTissues {
  LabelVolume segmentation;  // 0 background, 1 soft tissue, 2 enclosed air (sinus), 3 bone, 4 teeth
  LabelVolume jaws;          // phantom Tissue values: upper/lower teeth, mandible apart
  // segment_tissues' own labels (default options), before the sinus air is told apart: what the case's skin and
  // bone surfaces are traced in, kept so that they need not segment the CT again.
  LabelVolume ct_labels;

  // ct_labels if they are what segment_tissues would make with `options`, else nullptr.
  const LabelVolume* ct_labels_for(const SegmentationOptions& options) const {
    return !ct_labels.labels.empty() && options == SegmentationOptions{} ? &ct_labels : nullptr;
  }
};

// The case's primary CT series, segmented. Throws what volume loading and jaw separation throw.
CaseTissues load_case_tissues(Archive& archive, int64_t case_id, const LandmarkSet& landmarks);
// The same for a CT already in memory.
CaseTissues segment_case_tissues(const Volume& ct, const LandmarkSet& landmarks);

}  // namespace maxillo::casework
