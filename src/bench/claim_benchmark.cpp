#include "bench/claim_benchmark.h"

#include <mutex>
#include <thread>
#include <vector>

#include "archive/archive.h"
#include "archive/work_queue.h"
#include "bench/formatted.h"
#include "bench/scratch_archive.h"
#include "bench/timing.h"
#include "core/error.h"

namespace maxillo::bench {
namespace {

// Throws unless every item of the queue was claimed once and finished, and the workers counted
// as many claims as there are items.
void check_claimed_once(const WorkQueue& queue, size_t claimed, int items) {
  for (const auto& record : queue.records())
    if (record.claims != 1 || record.state != "done")
      throw Error(ErrorCode::kProcessing, record.item, "claimed " + std::to_string(record.claims) + " times");
  if (claimed != size_t(items)) throw Error(ErrorCode::kProcessing, "bench claim", "not every item was claimed once");
}

// Every worker claims and finishes until the queue is empty; returns claims per second.
double timed_claims(const std::filesystem::path& address, int items, int workers) {
  std::vector<std::string> names;
  for (int n = 0; n < items; ++n) names.push_back("item-" + std::to_string(1000000 + n));
  std::vector<Archive> archives;
  for (int w = 0; w < workers; ++w) archives.push_back(Archive::open(address));
  std::vector<WorkQueue> queues;  // one per worker, each on its worker's connection
  for (auto& archive : archives) queues.emplace_back(archive, "bench");
  queues.front().offer(names);
  std::mutex mutex;
  size_t claimed = 0;
  const auto start = Clock::now();
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      const std::string holder = "bench-worker-" + std::to_string(w);
      size_t mine = 0;
      while (auto item = queues[size_t(w)].claim(holder, 1000, 3600)) {
        queues[size_t(w)].finish(*item, holder, "done");
        ++mine;
      }
      std::lock_guard lock(mutex);
      claimed += mine;
    });
  for (auto& thread : threads) thread.join();
  const double seconds = seconds_since(start);
  check_claimed_once(queues.front(), claimed, items);
  return double(items) / seconds;
}

}  // namespace

Json run_claim_benchmark(const ClaimBenchOptions& options) {
  const auto workdir =
      options.workdir.empty() ? std::filesystem::temp_directory_path() / "maxillo-bench-claim" : options.workdir;
  std::vector<double> rates;
  for (int run = 0; run < options.runs; ++run) {
    ScratchArchive archive(options.postgres, workdir / ("archive" + std::to_string(run)), run);
    { Archive::open(archive.address(), OpenMode::CreateIfMissing); }
    rates.push_back(timed_claims(archive.address(), options.items, options.workers));
  }
  return {{"items", options.items},        {"workers", options.workers},
          {"runs", options.runs},          {"index", options.postgres.empty() ? "SQLite" : "PostgreSQL"},
          {"claims_per_s", median(rates)}, {"runs_claims_per_s", rates}};
}

std::string claim_benchmark_text(const Json& figures) {
  return formatted("%d items, %d workers at once, index on %s: %.0f claims/s (claim + finish; median of %d)\n",
                   figures["items"].get<int>(), figures["workers"].get<int>(),
                   figures["index"].get<std::string>().c_str(), figures["claims_per_s"].get<double>(),
                   figures["runs"].get<int>());
}

}  // namespace maxillo::bench
