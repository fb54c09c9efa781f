// Opening an archive: folder, index connection, schema upgrades one version at a time.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <thread>
#include <cstring>
#include <ctime>
#include <map>

#include "archive/archive_state.h"
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

int upgrade_schema(sqlite::Database& db) {
  auto steps = migrations();
  int newest = steps.empty() ? 0 : steps.rbegin()->first;
  int current = db.user_version();
  if (current > newest)
    throw Error(ErrorCode::kSchemaTooNew, db.file().string(),
                "schema version " + std::to_string(current) + ", this program knows up to " + std::to_string(newest));
  for (const auto& [version, path] : steps) {
    if (version <= current) continue;
    sqlite::Transaction transaction(db);
    if (db.user_version() >= version) continue;  // another process upgraded meanwhile
    db.execute(load_resource(path));
    db.execute("PRAGMA user_version = " + std::to_string(version));
    transaction.commit();
  }
  return db.user_version();
}

}  // namespace

std::string utc_now() {
  std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

void configure_connection(sqlite::Database& db) {
  // WAL: readers never block the writer; synchronous=NORMAL in WAL keeps the index consistent
  // after a crash (a lost last commit only leaves orphan objects, which verify --repair removes).
  db.execute("PRAGMA journal_mode = WAL");
  db.execute("PRAGMA synchronous = NORMAL");
  db.execute("PRAGMA foreign_keys = ON");
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

Archive::State::State(const std::filesystem::path& archive_folder)
    : folder(archive_folder),
      db((std::filesystem::create_directories(archive_folder), index_file(archive_folder))),
      objects(archive_folder / "objects") {}

Archive Archive::open(const std::filesystem::path& folder) {
  initialise_dicom_toolkit();
  std::unique_ptr<State> state;
  try {
    state = std::make_unique<State>(folder);
  } catch (const std::filesystem::filesystem_error& e) {
    throw Error(ErrorCode::kWriteFailed, folder.string(), e.code().message());
  }
  // Two processes creating the same archive at once: switching a new file to WAL and the first
  // upgrade can report "locked" without waiting on the busy handler. Retry them briefly.
  for (int attempt = 0;; ++attempt) {
    try {
      configure_connection(state->db);
      state->schema_version = upgrade_schema(state->db);
      break;
    } catch (const Error& e) {
      if (e.code() != ErrorCode::kArchiveBusy || attempt == 200) throw;
      std::this_thread::sleep_for(std::chrono::milliseconds(10 + attempt % 40));
    }
  }
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
