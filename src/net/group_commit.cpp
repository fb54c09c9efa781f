#include "net/group_commit.h"

#include <map>

#include "core/error.h"

namespace maxillo::net {

GroupCommit::GroupCommit(std::filesystem::path archive)
    : archive_dir_(std::move(archive)), committer_([this] { run(); }) {}

GroupCommit::~GroupCommit() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  committer_.join();
}

GroupCommit::Result GroupCommit::archive(const std::filesystem::path& file, const std::string& source) {
  std::future<Result> result;
  {
    std::lock_guard lock(mutex_);
    queue_.push_back({file, source, {}});
    result = queue_.back().result.get_future();
  }
  wake_.notify_one();
  return result.get();
}

void GroupCommit::run() {
  for (;;) {
    std::vector<Waiting> group;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, and nothing waits
      for (auto& waiting : queue_) group.push_back(std::move(waiting));
      queue_.clear();
    }
    archive_group(group);
  }
}

// One import per recorded source (an import records one source for all its files).
void GroupCommit::archive_group(std::vector<Waiting>& group) {
  std::map<std::string, std::vector<Waiting*>> by_source;
  for (auto& waiting : group) by_source[waiting.source].push_back(&waiting);
  for (auto& [source, files] : by_source) archive_from_one_source(files);
}

void GroupCommit::archive_from_one_source(std::vector<Waiting*>& files) {
  std::map<std::filesystem::path, Result> results;
  try {
    if (!archive_) archive_.emplace(Archive::open(archive_dir_));
    std::vector<std::filesystem::path> paths;
    for (const Waiting* waiting : files) paths.push_back(waiting->file);
    ImportOptions options;
    options.progress = ProgressDisplay::Never;
    options.batch_files = paths.size();  // one durable batch for the whole group
    options.source_label = files.front()->source;
    options.on_archived = [&](const std::filesystem::path& path, ImportOutcome outcome) {
      results[path] = {outcome, {}, {}};
    };
    options.on_problem = [&](const ImportProblem& problem) {
      results[problem.path] = {problem.outcome, problem.code, problem.reason};
    };
    archive_->import_paths(paths, options);
  } catch (const std::exception& error) {
    // Nothing of this group is known to be durable: every file is answered with the failure.
    for (Waiting* waiting : files)
      waiting->result.set_value({ImportOutcome::Failed, ErrorCode::kWriteFailed, error.what()});
    archive_.reset();  // reopened for the next group
    return;
  }
  for (Waiting* waiting : files) {
    const auto found = results.find(waiting->file);
    waiting->result.set_value(found != results.end() ? found->second
                                                     : Result{ImportOutcome::Failed, ErrorCode::kProcessing,
                                                              "the archive did not take the instance"});
  }
}

}  // namespace maxillo::net
