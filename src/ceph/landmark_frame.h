#pragma once
// The anatomical (Frankfort) frame of a landmark set: PoR, PoL, OrR and OrL handed to
// geometry's frankfort_frame, which says how the frame is built and when it falls back to the
// patient axes.
#include "ceph/landmark.h"
#include "geometry/anatomical_frame.h"

namespace maxillo {

AnatomicalFrame anatomical_frame(const LandmarkSet& landmarks);

}  // namespace maxillo
