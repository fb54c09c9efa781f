#pragma once
// The "landmarks" section of the consultation report: every landmark the case works with, so a
// surgeon can check them at a glance: label, position (LPS mm), where it came from (a file or
// the automatic detection), the detection's confidence and status (flagged ones with their
// failed checks; absent ones with the reason); and, when an automatic set was stored beside a set
// given by hand, how far each automatic landmark lies from the given one; when the case works
// with an automatic set and a reference set is known (a phantom's design), how far each lies
// from its true place. With the pictures of
// casework/landmarks/landmark_views.h the section opens with the landmarks drawn on bone and skin.
#include <optional>
#include <vector>

#include "casework/landmarks/landmark_views.h"
#include "records/case_landmarks.h"
#include "report/report_model.h"

namespace maxillo::sections {

// nullopt: the case has no landmarks (the section is left out; the summary says why).
// `automatic_beside`: an automatic set stored beside a set given by hand (which the case uses):
// the distance of each of its landmarks from the given one is shown after the table.
// `pictures`: the set drawn on bone and skin (casework::landmark_views), shown first.
// `reference`: a set known to be true (records::LandmarkOrigin::kReference); when the case works
// with an automatic set, the distance of each of its landmarks from the true place is shown.
std::optional<report::Section> landmark_section(const std::optional<records::StoredLandmarks>& stored,
                                                const std::optional<records::StoredLandmarks>& automatic_beside = {},
                                                const std::vector<casework::LandmarkView>& pictures = {},
                                                const std::optional<records::StoredLandmarks>& reference = {});

}  // namespace maxillo::sections
