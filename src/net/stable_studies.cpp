#include "net/stable_studies.h"

namespace maxillo::net {

void StableStudies::archived(const std::string& study_uid, Clock::time_point when) {
  std::lock_guard lock(mutex_);
  Study& study = studies_[study_uid];
  study.last_archived = std::max(study.last_archived, when);
  ++study.changes;
}

std::vector<std::string> StableStudies::take_due(Clock::time_point now) {
  std::lock_guard lock(mutex_);
  std::vector<std::string> due;
  for (auto& [uid, study] : studies_)
    if (study.changes != study.changes_done && now - study.last_archived >= quiet_) {
      study.changes_done = study.changes;
      due.push_back(uid);
    }
  return due;
}

bool StableStudies::changed_since_due(const std::string& study_uid) {
  std::lock_guard lock(mutex_);
  const auto found = studies_.find(study_uid);
  return found != studies_.end() && found->second.changes != found->second.changes_done;
}

}  // namespace maxillo::net
