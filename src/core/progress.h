#pragma once
// A progress bar on standard error when it is a terminal; silent otherwise (logs, CI, pipes).
#include <chrono>
#include <cstddef>
#include <string>

namespace maxillo {

enum class ProgressDisplay { Auto, Never };

class Progress {
 public:
  // total: number of steps expected (0 when unknown). Draws at most ~10 times a second.
  Progress(std::string label, size_t total, ProgressDisplay display = ProgressDisplay::Auto);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(size_t steps = 1);
  void finish();

 private:
  void draw(bool final_draw);

  std::string label_;
  size_t total_;
  size_t done_ = 0;
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace maxillo
