#pragma once
// The landmarks a case works with when nobody placed them: a case with no landmark set gets the
// set detected on its CT (landmarking/landmark_detection.h), stored as an automatic set with its
// method, confidences, flags and absences (records/case_landmarks.h), so that the report, the
// plan, the prediction and the validation work on a real CT without a landmark file. A set given
// by hand always takes precedence. A flagged landmark (a failed check, weak evidence) is not used
// for planning until a person confirms it (`maxillo ceph add`) or the planner accepts it.
#include <cstdint>
#include <string>

#include "archive/archive.h"
#include "core/volume.h"
#include "landmarking/landmark_detection.h"
#include "records/case_landmarks.h"

namespace maxillo::casework {

// The facts of a detection as the archive keeps them.
records::AutomaticFacts automatic_facts(const landmarking::LandmarkDetection& detection);

// The preferred stored set (by hand before automatic); when the case has none and a CT, the set
// detected on its CT now and stored. nullopt for a case without landmarks and without a CT.
// `ct`: the case's CT when the caller has it loaded.
std::optional<records::StoredLandmarks> case_landmarks(Archive& archive, int64_t case_id, const Volume* ct = nullptr);

// The labels planning reads (bone and teeth; not the soft tissue, not Ar and Go).
bool used_for_planning(const std::string& label);

// Each flagged landmark of an automatic set that planning uses, as "label (its failed checks)";
// none for a set given by hand.
std::vector<std::string> flagged_for_planning(const records::StoredLandmarks& set);

// Error(kBadValue, subject) naming each flagged landmark that planning uses, with its failed
// checks and how to go on, unless the set was given by hand or `accept_flagged`.
void require_confirmed_landmarks(const records::StoredLandmarks& set, const std::string& subject, bool accept_flagged);

}  // namespace maxillo::casework
