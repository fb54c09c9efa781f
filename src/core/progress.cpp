#include "core/progress.h"

#include <unistd.h>

#include <cstdio>

namespace maxillo {

Progress::Progress(std::string label, size_t total, ProgressDisplay display)
    : label_(std::move(label)),
      total_(total),
      enabled_(display == ProgressDisplay::Auto && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() { finish(); }

void Progress::advance(size_t steps) {
  done_ += steps;
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  draw(false);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (enabled_ && done_ > 0) draw(true);
}

void Progress::draw(bool final_draw) {
  constexpr int kWidth = 30;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double rate = seconds > 0 ? done_ / seconds : 0.0;
  if (total_ > 0) {
    double fraction = std::min(1.0, static_cast<double>(done_) / total_);
    int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r%s [%.*s%*s] %zu/%zu (%.0f/s)", label_.c_str(), filled, "##############################",
                 kWidth - filled, "", done_, total_, rate);
  } else {
    std::fprintf(stderr, "\r%s %zu (%.0f/s)", label_.c_str(), done_, rate);
  }
  if (final_draw) std::fputc('\n', stderr);
  std::fflush(stderr);
}

}  // namespace maxillo
