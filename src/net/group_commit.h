#pragma once
// Group commit for the storage server: the files that concurrent associations have received are
// archived together, one import (one sync of the group's files, one transaction) for every
// file waiting when the previous import ended, instead of one import each. Each caller still waits for its own file's
// outcome, so nothing is acknowledged before it is durable; a lone association pays what it paid
// before (its groups hold one file), several share the cost of the sync and the commit.
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "archive/archive.h"

namespace maxillo::net {

class GroupCommit {
 public:
  // The archive is opened by the committing thread, at its first group.
  explicit GroupCommit(std::filesystem::path archive);
  // Archives what is waiting, then stops.
  ~GroupCommit();
  GroupCommit(const GroupCommit&) = delete;
  GroupCommit& operator=(const GroupCommit&) = delete;

  struct Result {
    ImportOutcome outcome = ImportOutcome::Failed;
    ErrorCode code = ErrorCode::kProcessing;  // for a conflict or a failure
    std::string reason;
  };
  // Blocks until `file` is durably archived (Imported, AlreadyArchived) or refused. `source` is
  // recorded as its source (ImportOptions::source_label). Any thread.
  Result archive(const std::filesystem::path& file, const std::string& source);

 private:
  struct Waiting {
    std::filesystem::path file;
    std::string source;
    std::promise<Result> result;
  };
  void run();
  void archive_group(std::vector<Waiting>& group);
  void archive_from_one_source(std::vector<Waiting*>& files);

  std::filesystem::path archive_dir_;
  std::optional<Archive> archive_;  // the committing thread's
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Waiting> queue_;
  bool stopping_ = false;
  std::thread committer_;
};

}  // namespace maxillo::net
