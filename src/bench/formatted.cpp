#include "bench/formatted.h"

#include <cstdarg>
#include <cstdio>

namespace maxillo::bench {

std::string formatted(const char* format, ...) {
  va_list arguments;
  va_start(arguments, format);
  va_list measuring;
  va_copy(measuring, arguments);
  const int length = std::vsnprintf(nullptr, 0, format, measuring);
  va_end(measuring);
  std::string text(size_t(length > 0 ? length : 0), '\0');
  std::vsnprintf(text.data(), text.size() + 1, format, arguments);  // writes the closing '\0' past size()
  va_end(arguments);
  return text;
}

}  // namespace maxillo::bench
