#include "bench/timing.h"

#include <algorithm>
#include <cassert>

namespace maxillo::bench {

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> values) {
  assert(!values.empty() && "the median of no runs");
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace maxillo::bench
