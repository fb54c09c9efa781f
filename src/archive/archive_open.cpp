// Opening an archive: folder or server, index connection, schema upgrades one version at a time.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <thread>
#include <cstring>
#include <map>

#include "archive/archive_health.h"
#include "archive/archive_state.h"
#include "archive/journal_replay.h"
#include "archive/journalled_transaction.h"
#include "archive/postgres.h"
#include "core/log.h"
#include "core/resources.h"
#include "dicom/dicom_header.h"

namespace maxillo {
namespace {

// db/NNN_name.sql -> NNN. Versions must run 1, 2, 3... without gaps.
std::map<int, std::string> migrations() {
  std::map<int, std::string> by_version;
  for (const auto& path : list_resources("db/")) {
    std::string_view name = std::string_view(path).substr(3);
    int version = 0;
    auto [end, status] = std::from_chars(name.data(), name.data() + name.size(), version);
    if (status != std::errc() || !std::string_view(path).ends_with(".sql")) continue;
    by_version.emplace(version, path);
  }
  int expected = 1;
  for (const auto& [version, path] : by_version) {
    (void)path;
    if (version != expected++)
      throw Error(ErrorCode::kProcessing, "db/", "schema migrations are not numbered 1, 2, 3...");
  }
  return by_version;
}

// The migration to `version` for this connection's engine: db/DIALECT/NNN_*.sql where its
// engine needs its own (db/postgresql/), else the shared db/NNN_*.sql.
std::string migration_for(const db::Connection& db, const std::string& shared_path) {
  if (const std::string dialect = db.migration_dialect(); !dialect.empty()) {
    const std::string variant = "db/" + dialect + "/" + shared_path.substr(3);
    if (!list_resources(variant).empty()) return load_resource(variant);
  }
  return load_resource(shared_path);
}

// Version 2 introduced the journal: the rows an index already had are journalled as one entry.
void snapshot_rows(JournalledTransaction& transaction) {
  for (const auto& table : index_tables()) transaction.all_rows_of(table);
}

void prepare_folder(const std::filesystem::path& folder, OpenMode mode) {
  std::error_code error;
  if (std::filesystem::is_directory(folder, error)) {
    if (mode == OpenMode::Existing && !std::filesystem::exists(index_file(folder)) &&
        !holds_any_file(objects_folder(folder)))
      throw Error(ErrorCode::kNotFound, folder.string(), "not a maxillo archive (`maxillo import` creates one)");
    return;
  }
  if (std::filesystem::exists(folder, error))
    throw Error(ErrorCode::kWriteFailed, folder.string(), "not a folder, so it cannot hold an archive");
  if (mode == OpenMode::Existing)
    throw Error(ErrorCode::kNotFound, folder.string(), "no archive here (`maxillo import` creates one)");
  std::filesystem::create_directories(folder, error);
  if (error) throw Error(ErrorCode::kWriteFailed, folder.string(), error.message());
}

}  // namespace

int upgrade_schema(db::Connection& db, const IndexJournal& journal) {
  auto steps = migrations();
  int newest = steps.empty() ? 0 : steps.rbegin()->first;
  int current = db.schema_version();
  if (current > newest)
    throw Error(ErrorCode::kSchemaTooNew, db.name(),
                "schema version " + std::to_string(current) + ", this program knows up to " + std::to_string(newest));
  for (const auto& [version, path] : steps) {
    if (version <= current) continue;
    // An exclusive transaction holds the whole index (an advisory lock on PostgreSQL): of two
    // nodes starting at once, the second finds the work done.
    JournalledTransaction transaction(db, journal, "snapshot", db::TransactionKind::Exclusive);
    const int found = db.schema_version();
    if (found >= version) continue;
    db.execute(migration_for(db, path));
    if (version == 2 && found == 1) snapshot_rows(transaction);
    db.set_schema_version(version);
    transaction.commit();
  }
  return db.schema_version();
}

namespace {

// `archive rebuild-index` holds the store lock alone and swaps a new index file in. A process
// that opened the archive before and waited for the lock would otherwise write into the index
// that was replaced (kept beside as index.sqlite.replaced-*), and its rows would be lost to
// the archive: it follows the swap, on the index the archive has now.
void follow_a_rebuilt_index(Archive::State& state) {
  if (!state.db.reopen_if_moved()) return;
  log::info("the archive's index was rebuilt while this command waited; it goes on with the new index");
  require_intact_index(state.db);
  state.schema_version = state.db.schema_version();
  state.journal.settle(journal_sequence(state.db));
  require_index_not_behind_journal(state.db, state.journal);
}

// flock(2) on FOLDER/store.lock; returns the descriptor whose closing releases it.
int lock_store_file(const std::filesystem::path& folder, LockKind kind,
                    StoreLock::LockFile file = StoreLock::LockFile::CreateIfMissing) {
  auto path = folder / "store.lock";
  const bool existing_only = file == StoreLock::LockFile::ExistingOnly;
  int fd = ::open(path.c_str(), existing_only ? O_RDONLY | O_CLOEXEC : O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0 && existing_only && errno == ENOENT) return -1;
  if (fd < 0) throw Error(ErrorCode::kWriteFailed, path.string(), std::strerror(errno));
  while (::flock(fd, kind == LockKind::Shared ? LOCK_SH : LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    int error_number = errno;
    ::close(fd);
    throw Error(ErrorCode::kArchiveBusy, path.string(), std::strerror(error_number));
  }
  return fd;
}

}  // namespace

StoreLock::StoreLock(Archive::State& state, LockKind kind) : kind_(kind) {
  if (state.location.embedded()) {
    fd_ = lock_store_file(state.location.folder, kind);
    follow_a_rebuilt_index(state);
    return;
  }
  server_ = state.server_index;
  server_->lock(postgres::kStoreLockKey, kind == LockKind::Shared);
}

StoreLock::StoreLock(const std::filesystem::path& folder, LockKind kind, LockFile file)
    : fd_(lock_store_file(folder, kind, file)), kind_(kind) {}

StoreLock::~StoreLock() {
  if (server_) server_->unlock(postgres::kStoreLockKey, kind_ == LockKind::Shared);
  if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

Archive::State::State(ArchiveLocation where, OpenedIndex index)
    : location(std::move(where)),
      connection(std::move(index.connection)),
      db(*connection),
      file_index(index.file),
      server_index(index.server),
      objects(location.objects_folder()),
      journal(journal_folder(location)) {}

OpenedIndex open_index(const ArchiveLocation& location, sqlite::OpenKind open_kind) {
  OpenedIndex opened;
  if (location.embedded()) {
    auto file = std::make_unique<sqlite::Database>(index_file(location.folder), open_kind);
    opened.file = file.get();
    opened.connection = std::move(file);
  } else {
    auto server = std::make_unique<postgres::Connection>(location.server_uri);
    opened.server = server.get();
    opened.connection = std::move(server);
  }
  return opened;
}

std::unique_ptr<db::Connection> connect_index(const ArchiveLocation& location, sqlite::OpenKind open_kind) {
  return open_index(location, open_kind).connection;
}

namespace {

// An embedded archive: the folder is made for CreateIfMissing, and a missing or empty index
// beside stored objects is refused (archive_health.h).
// An archive this process may only read (a read-only mount, files it may not write): its index
// is opened read-only with nothing made beside it, so that reading commands work (issue 29: a
// read-only archive's `list` failed with "attempt to write a readonly database").
bool only_readable(const std::filesystem::path& folder) {
  return ::access(index_file(folder).c_str(), W_OK) != 0 || ::access(folder.c_str(), W_OK) != 0;
}

std::unique_ptr<Archive::State> open_embedded(const ArchiveLocation& location, OpenMode mode) {
  prepare_folder(location.folder, mode);
  const IndexPresence presence = check_index_presence(location.folder);
  const sqlite::OpenKind kind = presence == IndexPresence::Fresh ? sqlite::OpenKind::Create
                                : only_readable(location.folder) ? sqlite::OpenKind::ReadOnlyUntouched
                                                                 : sqlite::OpenKind::Existing;
  if (kind == sqlite::OpenKind::ReadOnlyUntouched) log::debug("the archive is read-only here: its index is only read");
  std::unique_ptr<Archive::State> state;
  try {
    state = std::make_unique<Archive::State>(location, open_index(location, kind));
  } catch (const std::filesystem::filesystem_error& e) {
    throw Error(ErrorCode::kWriteFailed, location.folder.string(), e.code().message());
  }
  require_intact_index(state->db);
  return state;
}

// `archive rebuild-index` fills a server archive's new, empty database while it holds the store
// lock alone, in its own transactions: a command opening the database meanwhile finds it empty
// or behind its journal, and is told to wait rather than that the index is lost (issue 29).
void refuse_while_rebuilding(Archive::State& state) {
  postgres::Connection& server = *state.server_index;
  if (server.try_lock(postgres::kStoreLockKey, true)) {
    server.unlock(postgres::kStoreLockKey, true);
    return;
  }
  throw Error(
      ErrorCode::kArchiveBusy, state.location.shown,
      "the archive's index is being rebuilt: `archive rebuild-index` (or `verify`) holds the archive alone; run "
      "the command again when it has finished");
}

// A server archive: the shared object folder must exist (it is made once, on the shared
// storage, not by whichever node comes first), and a database without a schema is a new
// archive only while that folder holds nothing.
std::unique_ptr<Archive::State> open_on_server(const ArchiveLocation& location, OpenMode mode) {
  std::error_code error;
  if (!std::filesystem::is_directory(location.folder, error))
    throw Error(
        ErrorCode::kBadArchiveAddress, location.shown,
        "the shared object folder " + location.folder.string() + " does not exist (make it on the shared storage)");
  auto state = std::make_unique<Archive::State>(location, open_index(location, sqlite::OpenKind::Existing));
  if (state->db.schema_version() == 0) {
    refuse_while_rebuilding(*state);
    if (holds_any_file(location.objects_folder()))
      throw Error(ErrorCode::kIndexDamaged, location.shown,
                  "the index database is empty but the shared object folder holds archived data; it is never "
                  "re-created empty over them: rebuild it from the folder with `maxillo --archive ADDRESS archive "
                  "rebuild-index` (or restore the database from its backup)");
    if (mode == OpenMode::Existing)
      throw Error(ErrorCode::kNotFound, location.shown,
                  "no archive in this database yet (`maxillo import` creates one)");
  }
  return state;
}

}  // namespace

Archive Archive::open(const std::filesystem::path& where, OpenMode mode) {
  initialise_dicom_toolkit();
  const ArchiveLocation location = parse_archive_location(where.string());
  std::unique_ptr<State> state = location.embedded() ? open_embedded(location, mode) : open_on_server(location, mode);
  // Two processes creating the same archive at once: switching a new file to WAL and the first
  // upgrade can report "locked" without waiting on the busy handler. Retry them briefly.
  for (int attempt = 0;; ++attempt) {
    try {
      if (state->file_index) state->file_index->use_archive_settings();
      state->schema_version = upgrade_schema(state->db, state->journal);
      break;
    } catch (const Error& e) {
      if (e.code() != ErrorCode::kArchiveBusy || attempt == 200) throw;
      std::this_thread::sleep_for(std::chrono::milliseconds(10 + attempt % 40));
    }
  }
  // The last entry's writer may have died between its COMMIT and its mark: the counter proves
  // the commit, so it is marked (best effort: a read-only archive's readers do without it).
  state->journal.settle(journal_sequence(state->db));
  try {
    require_index_not_behind_journal(state->db, state->journal);
  } catch (const Error& e) {
    if (e.code() == ErrorCode::kIndexDamaged && !location.embedded()) refuse_while_rebuilding(*state);
    throw;
  }
  if (mode != OpenMode::MigrationTarget) require_no_unfinished_migration(location.objects_folder(), location.shown);
  state->address = where;
  return Archive(std::move(state));
}

int Archive::newest_schema_version() { return migrations().empty() ? 0 : migrations().rbegin()->first; }

Archive::Archive(std::unique_ptr<State> state) : state_(std::move(state)) {}
Archive::~Archive() = default;
Archive::Archive(Archive&&) noexcept = default;
Archive& Archive::operator=(Archive&&) noexcept = default;

const std::filesystem::path& Archive::folder() const { return state_->location.folder; }
const std::filesystem::path& Archive::address() const { return state_->address; }
bool Archive::embedded() const { return state_->location.embedded(); }
int Archive::schema_version() const { return state_->schema_version; }

std::string_view to_string(ImportOutcome outcome) {
  switch (outcome) {
    case ImportOutcome::Imported: return "imported";
    case ImportOutcome::AlreadyArchived: return "already archived";
    case ImportOutcome::Conflict: return "conflict";
    case ImportOutcome::Failed: return "failed";
  }
  return "?";
}

std::string to_string(ItemKind kind) {
  switch (kind) {
    case ItemKind::Patient: return "patient";
    case ItemKind::Study: return "study";
    case ItemKind::Series: return "series";
    case ItemKind::Instance: return "instance";
    case ItemKind::Case: return "case";
  }
  return "?";
}

}  // namespace maxillo
