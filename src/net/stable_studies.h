#pragma once
// Which received studies are "stable": nothing new archived for them for a quiet period. A study
// is due once per change: each newly archived instance makes it due again after the next quiet
// period, instances received again (already archived) change nothing. Plain bookkeeping with the
// clock passed in, so the rule is tested without waiting.
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace maxillo::net {

class StableStudies {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StableStudies(std::chrono::milliseconds quiet) : quiet_(quiet) {}

  // An instance of this study was archived anew at `when`. Any thread.
  void archived(const std::string& study_uid, Clock::time_point when);
  // The studies quiet since `now - quiet` that changed since they were last due, each marked
  // done for its current state. Any thread.
  std::vector<std::string> take_due(Clock::time_point now);
  // True when the study changed since it was last due (or was never due). Any thread.
  bool changed_since_due(const std::string& study_uid);

 private:
  struct Study {
    Clock::time_point last_archived;
    int64_t changes = 0;       // instances archived so far
    int64_t changes_done = 0;  // ... when the study was last due
  };
  std::chrono::milliseconds quiet_;
  std::mutex mutex_;
  std::map<std::string, Study> studies_;
};

}  // namespace maxillo::net
