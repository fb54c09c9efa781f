#pragma once
// Landmark sets attached to a case, stored in the archive as 3D Slicer markups (LPS) objects.
// (Time points and their history arrive with the cephalometry work; for now the newest set
// attached to a case is the case's landmarks.)
#include <cstdint>
#include <string>

#include "archive/archive.h"
#include "ceph/landmark.h"

namespace maxillo::pipeline {

// Stores the set and records it as a "landmarks" artefact of the case; `source` says where the
// points came from (a file name, "phantom (analytic)", ...).
void attach_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& landmarks, const std::string& source);

// The newest landmark set attached to the case; empty when there is none.
LandmarkSet latest_landmarks(const Archive& archive, int64_t case_id);

}  // namespace maxillo::pipeline
