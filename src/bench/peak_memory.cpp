#include "bench/peak_memory.h"

#include <sys/resource.h>

#include <fstream>
#include <limits>
#include <string>

namespace maxillo::bench {

long peak_memory_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

bool reset_resident_peak() {
  std::ofstream clear_refs("/proc/self/clear_refs");
  return bool(clear_refs << "5" << std::flush);
}

long resident_peak_kb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long value = 0;
  while (status >> key) {
    if (key == "VmHWM:" && status >> value) return value;
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 0;
}

}  // namespace maxillo::bench
