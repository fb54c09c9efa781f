#pragma once
// The demo's stage times: each mark() closes the stage that ran since the last mark, logs its
// seconds and keeps them for the summary ({"stages_seconds": {...}, "total_seconds": T}).
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "core/json.h"
#include "core/log.h"

namespace maxillo::demo {

class StageClock {
 public:
  void mark(const std::string& stage) {
    auto now = std::chrono::steady_clock::now();
    double seconds = std::chrono::duration<double>(now - last_).count();
    stages_.push_back({stage, seconds});
    log::info(stage, ": ", seconds, " s");
    last_ = now;
  }
  Json to_json() const {
    Json stages = Json::object();
    double total = 0;
    for (const auto& [name, seconds] : stages_) {
      stages[name] = seconds;
      total += seconds;
    }
    return {{"stages_seconds", stages}, {"total_seconds", total}};
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  std::vector<std::pair<std::string, double>> stages_;
};

}  // namespace maxillo::demo
