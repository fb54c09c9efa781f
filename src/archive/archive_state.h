#pragma once
// Archive's private state, shared by the archive_*.cpp files of this module only.
#include <filesystem>
#include <string>

#include "archive/archive.h"
#include "archive/object_store.h"
#include "archive/sqlite.h"

namespace maxillo {

// flock(2) on ARCHIVE/store.lock: writers of objects hold it shared, verify --repair holds it
// exclusively, so repair never deletes an object whose row is about to be committed. The kernel
// releases it when a process dies, so a kill -9 leaves no stale lock.
enum class LockKind { Shared, Exclusive };
class StoreLock {
 public:
  StoreLock(const std::filesystem::path& folder, LockKind kind);
  ~StoreLock();
  StoreLock(const StoreLock&) = delete;
  StoreLock& operator=(const StoreLock&) = delete;

 private:
  int fd_ = -1;
};

struct Archive::State {
  explicit State(const std::filesystem::path& archive_folder);
  std::filesystem::path folder;
  sqlite::Database db;
  ObjectStore objects;
  int schema_version = 0;
};

inline std::filesystem::path index_file(const std::filesystem::path& folder) { return folder / "index.sqlite"; }

// Connection settings shared by every connection to an archive index.
void configure_connection(sqlite::Database& db);

// UTC now as ISO 8601, e.g. 2024-05-01T12:00:00Z.
std::string utc_now();

}  // namespace maxillo
