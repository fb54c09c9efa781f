#include "archive/sqlite.h"

#include <sqlite3.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include "core/error.h"

namespace maxillo::sqlite {
namespace {
// How long a writer waits for another process before giving up with kArchiveBusy. Import
// batches hold the write lock for milliseconds, so this is generous.
constexpr int kBusyTimeoutMs = 30000;

// A damaged index file is not a transient database error: say how to recover.
ErrorCode code_for(int status) {
  switch (status & 0xFF) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED: return ErrorCode::kArchiveBusy;
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB: return ErrorCode::kIndexDamaged;
    case SQLITE_FULL: return ErrorCode::kWriteFailed;      // the disk is full: a write failed, nothing is damaged
    case SQLITE_READONLY: return ErrorCode::kWriteFailed;  // a read-only archive: reading works, writing cannot
    default: return ErrorCode::kDatabase;
  }
}

std::string with_recovery_hint(int status, std::string reason) {
  if (code_for(status) == ErrorCode::kIndexDamaged)
    reason += " (the index is damaged: `maxillo archive rebuild-index` rebuilds it from the object store)";
  return reason;
}
}  // namespace

namespace {
int open_flags(OpenKind kind) {
  switch (kind) {
    case OpenKind::Create: return SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX;
    case OpenKind::Existing: return SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX;
    case OpenKind::ReadOnly:
    case OpenKind::ReadOnlyUntouched: return SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX;
  }
  return 0;
}

// "file:PATH?immutable=1" with the path's URI-reserved characters escaped (RFC 3986).
std::string immutable_uri(const std::filesystem::path& file) {
  std::string uri = "file:";
  for (unsigned char c : file.string()) {
    if (c == '%' || c == '?' || c == '#' || c < 0x20 || c >= 0x7f) {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", c);
      uri += escaped;
    } else {
      uri += char(c);
    }
  }
  return uri + "?immutable=1";
}

bool has_write_ahead_log(const std::filesystem::path& file) {
  std::error_code error;
  const auto wal = std::filesystem::path(file.string() + "-wal");
  return std::filesystem::exists(wal, error) && std::filesystem::file_size(wal, error) > 0;
}

}  // namespace

Database::Database(const std::filesystem::path& file, OpenKind kind) : file_(file), name_(file.string()), kind_(kind) {
  open();
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::open() {
  const bool immutable = kind_ == OpenKind::ReadOnlyUntouched && !has_write_ahead_log(file_);
  const std::string name = immutable ? immutable_uri(file_) : file_.string();
  int status = sqlite3_open_v2(name.c_str(), &db_, open_flags(kind_) | (immutable ? SQLITE_OPEN_URI : 0), nullptr);
  if (status != SQLITE_OK) {
    std::string reason = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(status);
    sqlite3_close(db_);
    db_ = nullptr;
    throw Error(code_for(status), file_.string(), with_recovery_hint(status, "cannot open: " + reason));
  }
  sqlite3_busy_timeout(db_, kBusyTimeoutMs);
  sqlite3_extended_result_codes(db_, 1);
  if (archive_settings_) use_archive_settings();
}

void Database::use_archive_settings() {
  // WAL: readers never block the writer; synchronous=NORMAL in WAL keeps the index consistent
  // after a crash (a lost last commit only leaves orphan objects, which verify --repair removes).
  // Setting the journal mode writes the file: a read-only connection keeps the file's own.
  if (kind_ != OpenKind::ReadOnly && kind_ != OpenKind::ReadOnlyUntouched) {
    execute("PRAGMA journal_mode = WAL");
    execute("PRAGMA synchronous = NORMAL");
  }
  execute("PRAGMA foreign_keys = ON");
  // Checks each b-tree page as it is read, so damage is noticed where it is met.
  execute("PRAGMA cell_size_check = ON");
  archive_settings_ = true;
}

bool Database::reopen_if_moved() {
  int moved = 0;
  if (sqlite3_file_control(db_, "main", SQLITE_FCNTL_HAS_MOVED, &moved) != SQLITE_OK || !moved) return false;
  sqlite3_close_v2(db_);
  db_ = nullptr;
  if (kind_ == OpenKind::Create) kind_ = OpenKind::Existing;  // never an empty index where one vanished
  open();
  return true;
}

void Database::fail(int status, std::string_view what) const {
  throw Error(code_for(status), name_, with_recovery_hint(status, std::string(what) + ": " + sqlite3_errmsg(db_)));
}

void Database::execute(std::string_view sql) {
  std::string text(sql);
  char* message = nullptr;
  int status = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &message);
  if (status != SQLITE_OK) {
    std::string reason = message ? message : sqlite3_errstr(status);
    sqlite3_free(message);
    throw Error(code_for(status), name_, with_recovery_hint(status, reason));
  }
}

int Database::schema_version() {
  db::Statement query(*this, "PRAGMA user_version");
  return static_cast<int>(db::single_integer(query));
}

void Database::set_schema_version(int version) { execute("PRAGMA user_version = " + std::to_string(version)); }

int64_t Database::clock_seconds() {
  return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

namespace {

class SqliteStatement final : public db::PreparedStatement {
 public:
  SqliteStatement(Database& db, std::string_view sql) : db_(db) {
    int status = sqlite3_prepare_v3(db.handle(), sql.data(), static_cast<int>(sql.size()), SQLITE_PREPARE_PERSISTENT,
                                    &statement_, nullptr);
    if (status != SQLITE_OK) db.fail(status, "cannot prepare \"" + std::string(sql.substr(0, 60)) + "\"");
  }
  ~SqliteStatement() override { sqlite3_finalize(statement_); }

  void reset() override {
    sqlite3_reset(statement_);
    sqlite3_clear_bindings(statement_);
  }
  void bind_integer(int index, int64_t value) override { sqlite3_bind_int64(statement_, index, value); }
  void bind_real(int index, double value) override { sqlite3_bind_double(statement_, index, value); }
  void bind_text(int index, std::string_view text) override {
    // An empty string_view may hold no pointer at all, which SQLite would bind as NULL.
    sqlite3_bind_text(statement_, index, text.data() ? text.data() : "", static_cast<int>(text.size()),
                      SQLITE_TRANSIENT);
  }
  void bind_null(int index) override { sqlite3_bind_null(statement_, index); }

  bool step() override {
    int status = sqlite3_step(statement_);
    if (status == SQLITE_ROW) return true;
    if (status == SQLITE_DONE) {
      changed_ = sqlite3_stmt_readonly(statement_) ? 0 : sqlite3_changes(db_.handle());
      return false;
    }
    db_.fail(status, "query failed");
  }
  int rows_changed() const override { return changed_; }

  int column_count() const override { return sqlite3_column_count(statement_); }
  std::string column_name(int column) const override { return sqlite3_column_name(statement_, column); }
  db::ColumnType column_type(int column) const override {
    switch (sqlite3_column_type(statement_, column)) {
      case SQLITE_INTEGER: return db::ColumnType::Integer;
      case SQLITE_FLOAT: return db::ColumnType::Real;
      case SQLITE_NULL: return db::ColumnType::Null;
      default: return db::ColumnType::Text;  // the schema stores no blobs
    }
  }
  int64_t integer(int column) const override { return sqlite3_column_int64(statement_, column); }
  double real(int column) const override { return sqlite3_column_double(statement_, column); }
  std::string text(int column) const override {
    const auto* bytes = sqlite3_column_text(statement_, column);
    return bytes ? std::string(reinterpret_cast<const char*>(bytes), sqlite3_column_bytes(statement_, column))
                 : std::string();
  }

 private:
  Database& db_;
  sqlite3_stmt* statement_ = nullptr;
  int changed_ = 0;
};

}  // namespace

std::unique_ptr<db::PreparedStatement> Database::prepare(std::string_view sql) {
  return std::make_unique<SqliteStatement>(*this, sql);
}

void Database::begin(db::TransactionKind kind) {
  // The busy handler already waits kBusyTimeoutMs; BEGIN IMMEDIATE can still report BUSY at
  // once in WAL mode when a snapshot must be upgraded, so retry a few times with a pause.
  // One writer at a time: Immediate and Exclusive alike take the file's write lock at once.
  const char* sql = kind == db::TransactionKind::Deferred ? "BEGIN DEFERRED" : "BEGIN IMMEDIATE";
  for (int attempt = 0;; ++attempt) {
    int status = sqlite3_exec(db_, sql, nullptr, nullptr, nullptr);
    if (status == SQLITE_OK) return;
    if ((status & 0xFF) != SQLITE_BUSY || attempt == 50) fail(status, "cannot begin a transaction");
    std::this_thread::sleep_for(std::chrono::milliseconds(20 + 10 * attempt));
  }
}

void Database::rollback() noexcept { sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr); }

void Database::commit() {
  for (int attempt = 0;; ++attempt) {
    int status = sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr);
    if (status == SQLITE_OK) return;
    if ((status & 0xFF) != SQLITE_BUSY || attempt == 50) fail(status, "cannot commit");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void Database::make_read_only() { execute("PRAGMA query_only = ON"); }

std::string Database::quick_check() {
  db::Statement check(*this, "PRAGMA quick_check");
  return check.step() ? check.text(0) : "no answer";
}

std::string Database::integrity_check() {
  db::Statement check(*this, "PRAGMA integrity_check(20)");
  std::string findings;
  while (check.step()) findings += (findings.empty() ? "" : "; ") + check.text(0);
  return findings.empty() ? "no answer" : findings;
}

std::vector<std::string> Database::table_columns(const std::string& table) {
  db::Statement info(*this, "SELECT name FROM pragma_table_info(?1)");
  info.bind(1, table);
  std::vector<std::string> columns;
  while (info.step()) columns.push_back(info.text(0));
  return columns;
}

}  // namespace maxillo::sqlite
