#pragma once
// The orientation check of a case's CT, run once per CT content and kept in the archive
// (records/orientation_record.h), as every command that plans on the case needs it: a header
// that contradicts the anatomy stops planning and prediction (an input error naming the
// finding) until a person confirms the volume with `maxillo orientation CASE --confirm`.
#include <cstdint>

#include "archive/archive.h"
#include "core/volume.h"
#include "records/orientation_record.h"

namespace maxillo::casework {

// The stored record of the case's primary CT, or the check run now and stored. `ct`: the
// volume when the caller has it loaded already (else it is read from the archive).
records::OrientationRecord case_orientation(Archive& archive, int64_t case_id, const Volume* ct = nullptr);

// Throws Error(kBadValue) naming the case, the finding and how to go on, unless the record is
// trusted (records::OrientationRecord::trusted). `what` names the refused step ("planning").
void require_trusted_orientation(Archive& archive, int64_t case_id, const std::string& what);

// Records that a person looked at the volume and confirms it as it is.
records::OrientationRecord confirm_orientation(Archive& archive, int64_t case_id);

}  // namespace maxillo::casework
