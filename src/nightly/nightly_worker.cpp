#include "nightly/nightly_worker.h"

#include <unistd.h>

#include <atomic>
#include <charconv>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "core/log.h"
#include "records/validation_archive.h"
#include "casework/validation/validation_json.h"

namespace maxillo::nightly {
namespace {

std::string default_worker_name() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  return std::string(host) + ":" + std::to_string(::getpid());
}

// Renews a lease every third of its length, on a connection of its own, until destroyed.
class LeaseHeartbeat {
 public:
  LeaseHeartbeat(const std::filesystem::path& address, std::string item, std::string holder, int64_t lease_seconds)
      : thread_([this, address, item = std::move(item), holder = std::move(holder), lease_seconds] {
          try {
            renew_until_stopped(address, item, holder, lease_seconds);
          } catch (const std::exception& e) {  // the case goes on; at worst its lease ends and it is redone
            log::warning("nightly: cannot renew the lease of ", item, ": ", e.what());
          }
        }) {}
  void renew_until_stopped(const std::filesystem::path& address, const std::string& item, const std::string& holder,
                           int64_t lease_seconds) {
    Archive archive = Archive::open(address);
    WorkQueue queue(archive, kNightlyQueue);
    const auto period = std::chrono::milliseconds(std::max<int64_t>(200, lease_seconds * 1000 / 3));
    std::unique_lock lock(mutex_);
    while (!stop_.wait_for(lock, period, [this] { return stopping_; }))
      if (!queue.renew(item, holder, queue.clock_seconds() + lease_seconds))
        log::warning("nightly: the lease of ", item, " was lost");
  }

  ~LeaseHeartbeat() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    stop_.notify_one();
    thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

// The eligible cases without a validation of their current inputs, as work items.
std::vector<std::string> work_to_offer(const Archive& archive, const casework::ValidationOptions& options) {
  std::vector<int64_t> cases;
  for (const auto& c : archive.cases()) cases.push_back(c.id);
  std::vector<std::string> items;
  for (const auto& [case_id, inputs] : casework::validation_inputs_hashes(archive, cases, options)) {  // a few queries
    try {
      const auto key = nightly_key(inputs);
      if (key && !records::find_validation(archive, inputs.artefacts, *key))
        items.push_back(nightly_work_item(case_id, *key));
    } catch (const std::exception& e) {  // the case is reported; the others are offered
      log::error("case ", case_id, ": ", e.what());
    }
  }
  return items;
}

// Validates one claimed item and finishes it; returns what became of the case.
NightlyCase work_on(Archive& archive, WorkQueue& queue, const std::string& item, const NightlyOptions& options,
                    const std::string& holder) {
  const auto parsed = parse_nightly_work_item(item);
  NightlyCase result;
  auto finish = [&](const char* state, const std::string& reason) {
    if (!queue.finish(item, holder, state, reason))
      log::warning("nightly: ", item, " was taken over by another worker before it finished here");
  };
  if (!parsed) {
    finish("failed", "not a nightly work item");
    return result;
  }
  const auto& [case_id, key] = *parsed;
  result.case_id = case_id;
  try {
    const auto current = casework::validation_inputs_hash(archive, case_id, options.validation);
    if (current != key) {
      result.reason = "its inputs changed since it was offered";
      finish("superseded", result.reason);
      return result;
    }
    if (records::find_validation(archive, case_id, key)) {  // a worker that lost its lease stored it after all
      result.outcome = NightlyOutcome::kUpToDate;
      finish("done", "");
      return result;
    }
    const auto started = std::chrono::steady_clock::now();
    LeaseHeartbeat heartbeat(archive.address(), item, holder, options.lease_seconds);
    const auto validation = casework::validate_case(archive, case_id, options.validation,
                                                    options.out / ("case-" + std::to_string(case_id)));
    // A worker that stalled past its lease may have lost the case to another one, which then
    // stores the validation: store it only while the lease is still ours.
    if (!queue.renew(item, holder, queue.clock_seconds() + options.lease_seconds)) {
      result.reason = "its lease went to another worker while it ran; that worker stores the validation";
      log::warning("case ", case_id, ": ", result.reason);
      return result;
    }
    records::store_validation(archive, casework::validation_to_store(validation));
    result.outcome = NightlyOutcome::kValidated;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    finish("done", "");
  } catch (const std::exception& e) {
    result.outcome = NightlyOutcome::kFailed;
    result.reason = e.what();
    log::error("case ", case_id, ": validation failed: ", result.reason);
    finish("failed", result.reason);
  }
  return result;
}

}  // namespace

std::string nightly_work_item(int64_t case_id, const std::string& inputs_hash) {
  return "case:" + std::to_string(case_id) + ":" + inputs_hash;
}

NightlyCase unfinished_case(int64_t case_id, const WorkRecord* record, int64_t now) {
  static const std::string kFinish =
      "; `maxillo nightly --claim` (or scripts/cluster/nightly-slurm.sh again) finishes it, then `nightly "
      "--summary-only`";
  NightlyCase result{case_id, NightlyOutcome::kNotValidated, "", 0};
  if (record == nullptr) {
    result.reason = "not validated: no worker has offered it yet" + kFinish;
  } else if (record->state == "failed") {
    result.outcome = NightlyOutcome::kFailed;
    result.reason = "failed on worker " + record->holder + ": " + record->reason;
  } else if (record->state == "pending" && record->expires_at > now) {
    result.reason = "being validated by worker " + record->holder + " (lease for " +
                    std::to_string(record->expires_at - now) + " s more)";
  } else if (record->state == "pending" && record->claims > 0) {
    result.reason = "not validated: its worker " + record->holder + " stopped before finishing it" + kFinish;
  } else if (record->state == "pending") {
    result.reason = "not validated: no worker claimed it (the workers stopped first)" + kFinish;
  } else {
    result.reason = "not validated: its work item is " + record->state + " (" + record->reason + ")" + kFinish;
  }
  return result;
}

std::optional<std::pair<int64_t, std::string>> parse_nightly_work_item(const std::string& item) {
  if (!item.starts_with("case:")) return std::nullopt;
  const auto colon = item.find(':', 5);
  if (colon == std::string::npos) return std::nullopt;
  int64_t id = 0;
  auto [end, error] = std::from_chars(item.data() + 5, item.data() + colon, id);
  if (error != std::errc() || end != item.data() + colon) return std::nullopt;
  return std::make_pair(id, item.substr(colon + 1));
}

NightlyReport run_nightly_worker(Archive& archive, const NightlyOptions& options) {
  std::filesystem::create_directories(options.out);
  const std::string holder = options.worker.empty() ? default_worker_name() : options.worker;
  WorkQueue queue(archive, kNightlyQueue);
  queue.offer(work_to_offer(archive, options.validation));
  NightlyReport report;
  for (;;) {
    if (auto item = queue.claim(holder, queue.clock_seconds(), options.lease_seconds)) {
      auto result = work_on(archive, queue, *item, options, holder);
      log::info("case ", result.case_id, ": ", to_string(result.outcome));
      report.cases.push_back(std::move(result));
      continue;
    }
    const auto counts = queue.counts(queue.clock_seconds());
    if (counts.pending == 0 && counts.leased == 0) break;  // every item is finished
    // Others hold leases: wait, in case one of them dies and its case comes free.
    if (counts.pending == 0) std::this_thread::sleep_for(options.poll);
  }
  std::sort(report.cases.begin(), report.cases.end(), [](auto& a, auto& b) { return a.case_id < b.case_id; });
  return report;
}

}  // namespace maxillo::nightly
