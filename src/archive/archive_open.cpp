// Opening an archive: folder, index connection, schema upgrades one version at a time.
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
#include "archive/dicom_header.h"
#include "core/resources.h"

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
    if (version != expected++) throw Error(ErrorCode::kProcessing, "db/", "schema migrations are not numbered 1, 2, 3...");
  }
  return by_version;
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

int upgrade_schema(sqlite::Database& db, const IndexJournal& journal) {
  auto steps = migrations();
  int newest = steps.empty() ? 0 : steps.rbegin()->first;
  int current = db.user_version();
  if (current > newest)
    throw Error(ErrorCode::kSchemaTooNew, db.file().string(),
                "schema version " + std::to_string(current) + ", this program knows up to " + std::to_string(newest));
  for (const auto& [version, path] : steps) {
    if (version <= current) continue;
    JournalledTransaction transaction(db, journal, "snapshot");
    const int found = db.user_version();
    if (found >= version) continue;  // another process upgraded meanwhile
    db.execute(load_resource(path));
    if (version == 2 && found == 1) snapshot_rows(transaction);
    db.execute("PRAGMA user_version = " + std::to_string(version));
    transaction.commit();
  }
  return db.user_version();
}


void configure_connection(sqlite::Database& db) {
  // WAL: readers never block the writer; synchronous=NORMAL in WAL keeps the index consistent
  // after a crash (a lost last commit only leaves orphan objects, which verify --repair removes).
  db.execute("PRAGMA journal_mode = WAL");
  db.execute("PRAGMA synchronous = NORMAL");
  db.execute("PRAGMA foreign_keys = ON");
  // Checks each b-tree page as it is read, so damage is noticed where it is met.
  db.execute("PRAGMA cell_size_check = ON");
}

StoreLock::StoreLock(const std::filesystem::path& folder, LockKind kind) {
  auto path = folder / "store.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error(ErrorCode::kWriteFailed, path.string(), std::strerror(errno));
  while (::flock(fd_, kind == LockKind::Shared ? LOCK_SH : LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    int error_number = errno;
    ::close(fd_);
    throw Error(ErrorCode::kArchiveBusy, path.string(), std::strerror(error_number));
  }
}

StoreLock::~StoreLock() { ::close(fd_); }  // closing releases the flock

Archive::State::State(const std::filesystem::path& archive_folder, sqlite::OpenKind index_open)
    : folder(archive_folder),
      db(index_file(archive_folder), index_open),
      objects(objects_folder(archive_folder)),
      journal(journal_folder(archive_folder)) {}

Archive Archive::open(const std::filesystem::path& folder, OpenMode mode) {
  initialise_dicom_toolkit();
  prepare_folder(folder, mode);
  const IndexPresence presence = check_index_presence(folder);
  std::unique_ptr<State> state;
  try {
    state = std::make_unique<State>(folder, presence == IndexPresence::Fresh ? sqlite::OpenKind::Create
                                                                             : sqlite::OpenKind::Existing);
  } catch (const std::filesystem::filesystem_error& e) {
    throw Error(ErrorCode::kWriteFailed, folder.string(), e.code().message());
  }
  require_intact_index(state->db);
  // Two processes creating the same archive at once: switching a new file to WAL and the first
  // upgrade can report "locked" without waiting on the busy handler. Retry them briefly.
  for (int attempt = 0;; ++attempt) {
    try {
      configure_connection(state->db);
      state->schema_version = upgrade_schema(state->db, state->journal);
      break;
    } catch (const Error& e) {
      if (e.code() != ErrorCode::kArchiveBusy || attempt == 200) throw;
      std::this_thread::sleep_for(std::chrono::milliseconds(10 + attempt % 40));
    }
  }
  require_index_not_behind_journal(state->db, state->journal);
  return Archive(std::move(state));
}

int Archive::newest_schema_version() { return migrations().empty() ? 0 : migrations().rbegin()->first; }

Archive::Archive(std::unique_ptr<State> state) : state_(std::move(state)) {}
Archive::~Archive() = default;
Archive::Archive(Archive&&) noexcept = default;
Archive& Archive::operator=(Archive&&) noexcept = default;

const std::filesystem::path& Archive::folder() const { return state_->folder; }
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
