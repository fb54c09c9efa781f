#pragma once
// A CT segmentation (imaging/segmentation.h: soft tissue, enclosed air, bone, teeth) does not
// tell the upper jaw from the lower one; osteotomies and join points need it. This relabels
// it in the phantom's tissue convention (sample/phantom.h) from landmarks:
//   teeth above the occlusal plane are upper teeth, below it lower teeth (the plane through the
//   incisor and first molar contacts; an overbite of a few voxels is misassigned, which the
//   soft tissue model does not notice);
//   the mandible is the bone connected to menton once the teeth are set aside, with every
//   piece of bone more than 3 mm below the occlusal plane along the arches; searched below
//   the occlusal plane along the dental arches (where upper and lower alveolar bone touch
//   through the teeth) and below the occlusal plane + `ramus_height_mm` behind them (the rami),
//   so that neither the teeth nor a condyle touching its fossa join the skull to it.
#include "ceph/landmark.h"
#include "core/volume.h"

namespace maxillo::planning {

struct JawSeparationOptions {
  double ramus_height_mm =
      25;  // how far above the occlusal plane the rami may reach (more: the coronoid and the condyle touch the skull on a CT)
  double arch_behind_first_molar_mm = 18;    // where the dental arches end (behind the second molars)
  double condyle_in_front_of_porion_mm = 3;  // the mandible lies in front of this (with PoR, PoL)
  double below_occlusal_mm = 3;              // bone this far below the occlusal plane, along the arches, is mandible
};

// Input labels: 0 background, 1 soft tissue, 2 enclosed air, 3 bone, 4 teeth. Output: phantom
// Tissue values (0 air, 1 soft tissue, 2 bone, 3 upper teeth, 4 air inside the head,
// 6 lower teeth, 7 mandible). Needs U1 and L1 (or one of them), U6R/L6R and U6L/L6L (or one
// of each pair) or else ANS and PNS (the occlusal plane at the adults' mean tilt to the palate,
// jaw_separation.cpp), and Me; Error naming the missing landmark otherwise.
LabelVolume separate_jaws(const LabelVolume& ct_tissues, const LandmarkSet& landmarks,
                          const JawSeparationOptions& options = {});

}  // namespace maxillo::planning
