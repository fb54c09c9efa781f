#include "net/pending_studies.h"

#include <fstream>

#include "core/atomic_file.h"

namespace maxillo::net {

PendingStudies::PendingStudies(std::filesystem::path file) : file_(std::move(file)) {
  create_folders_durably(file_.parent_path());
  std::ifstream in(file_);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) studies_.insert(line);
}

std::vector<std::string> PendingStudies::studies() const {
  std::lock_guard lock(mutex_);
  return {studies_.begin(), studies_.end()};
}

void PendingStudies::add(const std::string& study_uid) {
  std::lock_guard lock(mutex_);
  if (studies_.insert(study_uid).second) save();
}

void PendingStudies::remove_if_settled(const std::string& study_uid, const std::function<bool()>& still_owed) {
  std::lock_guard lock(mutex_);
  if (still_owed() || studies_.erase(study_uid) == 0) return;
  save();
}

void PendingStudies::save() const {
  std::string text;
  for (const auto& study : studies_) text += study + "\n";
  write_file_atomically(file_, text);
}

}  // namespace maxillo::net
