#pragma once
// Archive's private state, shared by the archive_*.cpp files of this module only.
#include <filesystem>
#include <string>

#include "archive/archive.h"
#include "archive/archive_location.h"
#include "archive/index_connection.h"
#include "archive/index_journal.h"
#include "archive/object_store.h"
#include "archive/postgres.h"
#include "archive/sqlite.h"
#include "core/utc_time.h"

namespace maxillo {

// A connection to the archive's index, and its engine's own object where the archive needs what
// only that engine has: the embedded file's settings, the server's advisory locks.
struct OpenedIndex {
  std::unique_ptr<db::Connection> connection;
  sqlite::Database* file = nullptr;        // an embedded index, or
  postgres::Connection* server = nullptr;  // a server's database
};

struct Archive::State {
  State(ArchiveLocation where, OpenedIndex index);
  ArchiveLocation location;
  std::filesystem::path address;  // as given to Archive::open
  std::unique_ptr<db::Connection> connection;
  db::Connection& db;                            // *connection
  sqlite::Database* file_index = nullptr;        // *connection of an embedded archive
  postgres::Connection* server_index = nullptr;  // *connection of a server archive
  ObjectStore objects;
  IndexJournal journal;
  int schema_version = 0;
  // The de-identification secret of an archive that has none and cannot be given one (it is
  // read-only here): this process's own, so that one export's pseudonyms still agree.
  std::string unsaved_secret;
};

// The store lock: writers of objects hold it shared, verify --repair holds it exclusively, so
// repair never deletes an object whose row is about to be committed. Embedded archives take
// flock(2) on ARCHIVE/store.lock; server archives a session-level advisory lock in their
// database, which every node sees (flock on network file systems is not to be trusted). Both
// are released when the process dies, so a kill -9 leaves no stale lock.
enum class LockKind { Shared, Exclusive };
class StoreLock {
 public:
  StoreLock(Archive::State& state, LockKind kind);
  // An embedded archive's folder, before it has a connection (rebuild-index). ExistingOnly opens
  // the lock file read-only and never creates it (the source of a migration is not changed;
  // without the file, no writer has ever run there, and there is nothing to lock against).
  enum class LockFile { CreateIfMissing, ExistingOnly };
  StoreLock(const std::filesystem::path& folder, LockKind kind, LockFile file = LockFile::CreateIfMissing);
  ~StoreLock();
  StoreLock(const StoreLock&) = delete;
  StoreLock& operator=(const StoreLock&) = delete;

 private:
  int fd_ = -1;
  postgres::Connection* server_ = nullptr;
  LockKind kind_;
};

inline std::filesystem::path index_file(const std::filesystem::path& folder) { return folder / "index.sqlite"; }
inline std::filesystem::path objects_folder(const std::filesystem::path& folder) { return folder / "objects"; }
inline std::filesystem::path journal_folder(const std::filesystem::path& folder) {
  return objects_folder(folder) / "journal";
}
inline std::filesystem::path journal_folder(const ArchiveLocation& location) {
  return location.objects_folder() / "journal";
}

// Applies the schema migrations in db/ one version at a time; an index upgraded from version 1
// gets a snapshot journal entry of its rows. Returns the schema version.
int upgrade_schema(db::Connection& db, const IndexJournal& journal);

// The contents of these cases (record, patient, series with roles, studies), unsorted, read
// with three queries per 4,096 cases; ids with no case are left out.
std::map<int64_t, CaseContents> read_case_contents(db::Connection& db, const std::vector<int64_t>& case_ids);

// A new connection to the archive's index (import's scanning thread has its own), with its
// engine's object, or alone.
OpenedIndex open_index(const ArchiveLocation& location, sqlite::OpenKind open_kind);
std::unique_ptr<db::Connection> connect_index(const ArchiveLocation& location, sqlite::OpenKind open_kind);

}  // namespace maxillo
