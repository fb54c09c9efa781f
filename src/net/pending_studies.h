#pragma once
// The studies whose stable-study action is still owed: changed since their action last ran. Kept
// in a file (one Study Instance UID per line, replaced atomically) so that a server stopped or
// killed before a study's quiet period ended runs its action after the restart, instead of never.
//
// Ordering makes it safe without a lock shared with StableStudies: the receiving thread records
// the change in StableStudies before add(); remove_if() checks and removes under this object's
// lock. A change therefore either makes remove_if() keep the study, or is added after it left.
#include <filesystem>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace maxillo::net {

class PendingStudies {
 public:
  // Reads the file; a missing file means none. Error(kWriteFailed) when the folder cannot be made.
  explicit PendingStudies(std::filesystem::path file);

  std::vector<std::string> studies() const;
  // Records the study as owed; written durably (before the C-STORE is answered) when it is new.
  void add(const std::string& study_uid);
  // Removes the study (durably) unless `still_owed` says a change came after its action.
  void remove_if_settled(const std::string& study_uid, const std::function<bool()>& still_owed);

 private:
  void save() const;  // under mutex_

  std::filesystem::path file_;
  mutable std::mutex mutex_;
  std::set<std::string> studies_;
};

}  // namespace maxillo::net
