#pragma once
// An archived CT series read back as a volume. The archive stores files under their hash, so a
// problem with one slice (a gap, another orientation, unreadable pixels) is reported naming the
// file it was imported from, which is the one a person can look at, with its object beside it.
#include <cstdint>

#include "archive/archive.h"
#include "core/volume.h"

namespace maxillo::records {

// load_series_volume over the series' objects. Throws Error as it does, with the subject
// "<source path> (archived as <object path>)" when the error is about one slice.
Volume load_archived_series(const Archive& archive, int64_t series);

}  // namespace maxillo::records
