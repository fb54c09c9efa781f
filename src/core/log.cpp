#include "core/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace maxillo::log {
namespace {
std::atomic<Level> g_level{Level::Info};
std::mutex g_write_mutex;

const char* prefix(Level level) {
  switch (level) {
    case Level::Error: return "error: ";
    case Level::Warning: return "warning: ";
    case Level::Info: return "";
    case Level::Debug: return "debug: ";
  }
  return "";
}
}  // namespace

void set_level(Level level) { g_level = level; }
Level level() { return g_level; }

void write(Level at, const std::string& message) {
  std::lock_guard lock(g_write_mutex);
  std::fprintf(stderr, "maxillo: %s%s\n", prefix(at), message.c_str());
}

}  // namespace maxillo::log
