#pragma once
// How every benchmark times its work: wall-clock seconds of a piece of work, and the median of
// repeated runs (a single run's time is at the mercy of whatever else the machine does).
#include <chrono>
#include <vector>

namespace maxillo::bench {

using Clock = std::chrono::steady_clock;

// Wall-clock seconds from `start` to now.
double seconds_since(Clock::time_point start);

// Wall-clock seconds that work() takes.
template <class Work>
double seconds_of(Work&& work) {
  const auto start = Clock::now();
  work();
  return seconds_since(start);
}

// The median the benchmarks report: the middle value; of an even count the upper of the two
// middle ones, so that the figure is one run's own. `values` must not be empty.
double median(std::vector<double> values);

// The median of `runs` timed runs of work().
template <class Work>
double median_seconds(int runs, Work&& work) {
  std::vector<double> times;
  for (int run = 0; run < runs; ++run) times.push_back(seconds_of(work));
  return median(times);
}

}  // namespace maxillo::bench
