#include "casework/landmarks/automatic_landmarks.h"

#include <set>

#include "core/error.h"
#include "core/log.h"
#include "landmarking/detection_files.h"
#include "records/archived_series.h"
#include "records/derivation.h"

namespace maxillo::casework {

records::AutomaticFacts automatic_facts(const landmarking::LandmarkDetection& detection) {
  records::AutomaticFacts facts;
  facts.method = landmarking::kMethodVersion;
  for (const auto& l : detection.landmarks) {
    if (!l.position) {
      facts.absent[l.label] = l.note;
      continue;
    }
    facts.confidence[l.label] = l.confidence;
    if (l.flagged()) facts.flagged[l.label] = landmarking::failed_checks(l);
  }
  return facts;
}

std::optional<records::StoredLandmarks> case_landmarks(Archive& archive, int64_t case_id, const Volume* ct) {
  if (auto stored = records::preferred_landmarks(archive, case_id)) return stored;
  int64_t series = 0;
  try {
    series = records::primary_series(archive.case_contents(case_id));
  } catch (const Error& e) {
    if (e.code() != ErrorCode::kNotFound) throw;
    return std::nullopt;  // no CT to find them on
  }
  const Volume loaded = ct ? Volume{} : records::load_archived_series(archive, series);
  const std::string subject = "case:" + std::to_string(case_id);
  const auto detection = landmarking::detect_landmarks(ct ? *ct : loaded, subject);
  const auto facts = automatic_facts(detection);
  records::attach_automatic_landmarks(archive, case_id, detection.present(), facts);
  log::info(subject, ": no landmarks were attached; ", detection.present().size(), " detected automatically (",
            facts.flagged.size(), " flagged, ", facts.absent.size(), " absent) and stored");
  return records::preferred_landmarks(archive, case_id);
}

bool used_for_planning(const std::string& label) {
  static const std::set<std::string> labels = {"S",   "N",  "OrR", "OrL", "PoR", "PoL", "A",   "B",   "ANS", "PNS",
                                               "Pog", "Me", "Gn",  "U1",  "L1",  "U6R", "U6L", "L6R", "L6L"};
  return labels.count(label) > 0;
}

std::vector<std::string> flagged_for_planning(const records::StoredLandmarks& set) {
  std::vector<std::string> flagged;
  if (!set.automatic) return flagged;
  for (const auto& [label, why] : set.automatic->flagged)
    if (used_for_planning(label)) flagged.push_back(label + " (" + why + ")");
  return flagged;
}

void require_confirmed_landmarks(const records::StoredLandmarks& set, const std::string& subject, bool accept_flagged) {
  if (accept_flagged) return;
  std::string doubts;
  for (const std::string& doubt : flagged_for_planning(set)) doubts += (doubts.empty() ? "" : "; ") + doubt;
  if (doubts.empty()) return;
  throw Error(ErrorCode::kBadValue, subject,
              "automatic landmarks that failed their checks are not used for planning: " + doubts +
                  ". Confirm them by hand (place them in 3D Slicer and `maxillo ceph add`) or accept them with "
                  "--accept-flagged");
}

}  // namespace maxillo::casework
