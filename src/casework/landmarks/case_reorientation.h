#pragma once
// `maxillo orientation CASE --reorient`: a case whose CT header flipped an axis (the face
// posterior, the vertex inferior) gets a corrected copy of its CT, the original kept untouched.
// The copy is the same pixels with the patient frame reflected back about the volume's centre
// (imaging/axis_flip.h), written as a new DICOM series of the same study (its UID derived from
// the original's, so asking again changes nothing) and imported; it becomes the case's
// pre-operative CT and the original series stays in the case as "unassigned". The landmarks
// follow: a set given by hand on the flipped volume is mapped through the same reflection and
// stored as a newer version; an automatic set is detected again on the corrected CT.
//
// A person asks for this and so vouches that the fault was an axis flip: the anatomy shows which
// axis is reversed but not whether left and right were exchanged with it (a head looks alike).
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "archive/archive.h"
#include "records/orientation_record.h"

namespace maxillo::casework {

struct ReorientedCase {
  int64_t original_series = 0;
  int64_t corrected_series = 0;
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();  // patient axes reflected: diag(1, +-1, +-1)
  std::string flipped_axes;                            // "y", "z" or "y and z"
  bool landmarks_mapped = false;                       // a set given by hand was mapped
  bool landmarks_detected = false;                     // an automatic set was detected again
  records::OrientationRecord record;                   // the check on the corrected CT
};

// Error(kBadValue) naming the case when the header agrees with the anatomy, the check cannot
// tell, or the face points sideways (not an axis flip: correct the scan and import it again).
ReorientedCase reorient_case(Archive& archive, int64_t case_id);

}  // namespace maxillo::casework
