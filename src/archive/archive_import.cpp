// Archive::import_paths: a two-stage pipeline. A scanner thread reads, hashes and parses files
// (the CPU-heavy part); the calling thread stores objects and commits rows in durable batches
// (the I/O part). On 2 cores the two overlap; the queue between them is bounded so memory
// stays at a few dozen files whatever the input size.
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "archive/archive_state.h"
#include "archive/import_batch.h"
#include "archive/import_scan.h"
#include "core/log.h"

namespace maxillo {
namespace {

// A bounded single-producer single-consumer queue; close() marks the end of input. Bounded in
// files and in bytes, so a folder of large multi-frame files does not fill the memory.
class ScanQueue {
 public:
  void push(ScannedFile&& item) {
    std::unique_lock lock(mutex_);
    not_full_.wait(
        lock, [&] { return (items_.size() < kCapacity && (items_.empty() || bytes_ < kCapacityBytes)) || abandoned_; });
    if (abandoned_) return;
    bytes_ += item.bytes.size();
    items_.push_back(std::move(item));
    not_empty_.notify_one();
  }
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    not_empty_.notify_one();
  }
  // The consumer gave up (an exception): let the producer finish quickly.
  void abandon() {
    std::lock_guard lock(mutex_);
    abandoned_ = true;
    not_full_.notify_one();
  }
  bool abandoned() {
    std::lock_guard lock(mutex_);
    return abandoned_;
  }
  std::optional<ScannedFile> pop() {
    std::unique_lock lock(mutex_);
    not_empty_.wait(lock, [&] { return !items_.empty() || closed_; });
    if (items_.empty()) return std::nullopt;
    ScannedFile item = std::move(items_.front());
    items_.pop_front();
    bytes_ -= item.bytes.size();
    not_full_.notify_one();
    return item;
  }

 private:
  static constexpr size_t kCapacity = 64;
  static constexpr size_t kCapacityBytes = size_t(512) << 20;
  size_t bytes_ = 0;
  std::mutex mutex_;
  std::condition_variable not_full_, not_empty_;
  std::deque<ScannedFile> items_;
  bool closed_ = false;
  bool abandoned_ = false;
};

void report_problem(ImportReport& report, const ImportOptions& options, ImportProblem problem) {
  (problem.outcome == ImportOutcome::Conflict ? report.conflicts : report.failed)++;
  if (options.on_problem) options.on_problem(problem);
  report.problems.push_back(std::move(problem));
}

// An indexed object whose file has gone or no longer hashes to its name (verify reports it as
// missing or corrupt) is written again from the identical bytes being re-imported: re-importing
// the originals heals the archive. What is there is hashed before it is trusted.
bool restore_archived_object(ObjectStore& objects, const ScannedFile& file) {
  auto outcome = objects.put(file.sha256, file.bytes);
  if (outcome == ObjectStore::PutOutcome::AlreadyIntact) return false;
  objects.make_durable();
  log::warning(file.path.string(), ": restored the ", outcome == ObjectStore::PutOutcome::Replaced ? "damaged" : "lost",
               " archived object ", file.sha256.substr(0, 12), "...");
  return true;
}

}  // namespace

ImportReport Archive::import_paths(const std::vector<std::filesystem::path>& paths, const ImportOptions& options) {
  ImportReport report;
  FileList inputs = list_input_files(paths);
  for (auto& item : inputs.unreachable)
    report_problem(report, options, {item.path, ImportOutcome::Failed, item.code, item.reason});

  Progress progress("import", inputs.files.size(), options.progress);
  StoreLock lock(*state_, LockKind::Shared);
  ScanQueue queue;
  std::exception_ptr scanner_error;
  std::thread scanner([&] {
    try {
      FileScanner scanner_stage(state_->location);
      for (const auto& path : inputs.files) {
        if (queue.abandoned()) break;
        queue.push(scanner_stage.scan(path));
      }
    } catch (...) {
      scanner_error = std::current_exception();
    }
    queue.close();
  });

  BatchWriter writer(state_->db, state_->objects, state_->journal, options.source_label);
  auto commit = [&] {
    size_t pending = writer.pending();
    writer.commit(report, options);
    progress.advance(pending);
  };
  try {
    while (auto item = queue.pop()) {
      switch (item->stage) {
        case ScannedFile::Stage::Known:
          if (restore_archived_object(state_->objects, *item)) ++report.restored;
          ++report.already_archived;
          if (options.on_archived) options.on_archived(item->path, ImportOutcome::AlreadyArchived);
          progress.advance();
          break;
        case ScannedFile::Stage::Conflict:
        case ScannedFile::Stage::Failed:
          report_problem(report, options,
                         {item->path,
                          item->stage == ScannedFile::Stage::Conflict ? ImportOutcome::Conflict : ImportOutcome::Failed,
                          item->code, item->reason});
          progress.advance();
          break;
        case ScannedFile::Stage::Parsed: {
          log::debug("import ", item->path.string(), ": patient ", item->header.patient_id);
          auto path = item->path;
          std::string reason;
          switch (writer.add(std::move(*item), reason)) {
            case ImportOutcome::Imported: break;
            case ImportOutcome::AlreadyArchived:  // the same file twice in one batch
              ++report.already_archived;
              if (options.on_archived) options.on_archived(path, ImportOutcome::AlreadyArchived);
              progress.advance();
              break;
            default:
              report_problem(report, options, {path, ImportOutcome::Conflict, ErrorCode::kConflict, reason});
              progress.advance();
              break;
          }
          if (writer.pending() >= options.batch_files) commit();
          break;
        }
      }
    }
    commit();
  } catch (...) {
    queue.abandon();
    while (queue.pop()) {}
    scanner.join();
    throw;
  }
  scanner.join();
  if (scanner_error) std::rethrow_exception(scanner_error);
  progress.finish();
  return report;
}

}  // namespace maxillo
