#include "core/utc_time.h"

#include <ctime>

namespace maxillo {

std::string utc_time_text(const char* format) {
  std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);  // thread-safe, unlike std::gmtime
  char text[64];
  return std::string(text, std::strftime(text, sizeof text, format, &utc));
}

}  // namespace maxillo
