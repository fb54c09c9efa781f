#pragma once
// Archive's private state, shared by the archive_*.cpp files of this module only.
#include <filesystem>
#include <string>

#include "archive/archive.h"
#include "archive/index_journal.h"
#include "archive/object_store.h"
#include "archive/sqlite.h"
#include "core/utc_time.h"

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
  State(const std::filesystem::path& archive_folder, sqlite::OpenKind index_open);
  std::filesystem::path folder;
  sqlite::Database db;
  ObjectStore objects;
  IndexJournal journal;
  int schema_version = 0;
};

inline std::filesystem::path index_file(const std::filesystem::path& folder) { return folder / "index.sqlite"; }
inline std::filesystem::path objects_folder(const std::filesystem::path& folder) { return folder / "objects"; }
inline std::filesystem::path journal_folder(const std::filesystem::path& folder) { return objects_folder(folder) / "journal"; }

// Applies the schema migrations in db/ one version at a time; an index upgraded from version 1
// gets a snapshot journal entry of its rows. Returns the schema version.
int upgrade_schema(sqlite::Database& db, const IndexJournal& journal);

// Connection settings shared by every connection to an archive index.
void configure_connection(sqlite::Database& db);


}  // namespace maxillo
