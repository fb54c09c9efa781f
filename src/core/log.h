#pragma once
// Diagnostics on standard error. Patient names and IDs may only be logged at Debug:
// clinics collect logs, and a log is not a place for protected health information.
#include <sstream>
#include <string>

namespace maxillo::log {

enum class Level { Error = 0, Warning = 1, Info = 2, Debug = 3 };

void set_level(Level level);
Level level();
void write(Level level, const std::string& message);

template <typename... Parts>
void emit(Level at, const Parts&... parts) {
  if (at > level()) return;
  std::ostringstream out;
  (out << ... << parts);
  write(at, out.str());
}

template <typename... Parts>
void error(const Parts&... p) {
  emit(Level::Error, p...);
}
template <typename... Parts>
void warning(const Parts&... p) {
  emit(Level::Warning, p...);
}
template <typename... Parts>
void info(const Parts&... p) {
  emit(Level::Info, p...);
}
// The only level allowed to carry patient names or IDs.
template <typename... Parts>
void debug(const Parts&... p) {
  emit(Level::Debug, p...);
}

}  // namespace maxillo::log
