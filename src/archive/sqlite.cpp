#include "archive/sqlite.h"

#include <sqlite3.h>

#include <cassert>
#include <chrono>
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
    case OpenKind::ReadOnly: return SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX;
  }
  return 0;
}
}  // namespace

Database::Database(const std::filesystem::path& file, OpenKind kind) : file_(file) {
  int status = sqlite3_open_v2(file.c_str(), &db_, open_flags(kind), nullptr);
  if (status != SQLITE_OK) {
    std::string reason = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(status);
    sqlite3_close(db_);
    db_ = nullptr;
    throw Error(code_for(status), file.string(), with_recovery_hint(status, "cannot open: " + reason));
  }
  sqlite3_busy_timeout(db_, kBusyTimeoutMs);
  sqlite3_extended_result_codes(db_, 1);
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::fail(int status, std::string_view what) const {
  throw Error(code_for(status), file_.string(), with_recovery_hint(status, std::string(what) + ": " + sqlite3_errmsg(db_)));
}

void Database::execute(std::string_view sql) {
  std::string text(sql);
  char* message = nullptr;
  int status = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &message);
  if (status != SQLITE_OK) {
    std::string reason = message ? message : sqlite3_errstr(status);
    sqlite3_free(message);
    throw Error(code_for(status), file_.string(), with_recovery_hint(status, reason));
  }
}

int Database::user_version() {
  Statement query(*this, "PRAGMA user_version");
  query.step();
  return static_cast<int>(query.integer(0));
}

int64_t Database::last_insert_id() const { return sqlite3_last_insert_rowid(db_); }
int Database::changes() const { return sqlite3_changes(db_); }

Statement::Statement(Database& db, std::string_view sql) : db_(db) {
  int status = sqlite3_prepare_v3(db.handle(), sql.data(), static_cast<int>(sql.size()), SQLITE_PREPARE_PERSISTENT,
                                  &statement_, nullptr);
  if (status != SQLITE_OK) db.fail(status, "cannot prepare \"" + std::string(sql.substr(0, 60)) + "\"");
}

Statement::~Statement() { sqlite3_finalize(statement_); }

Statement& Statement::reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
  return *this;
}

Statement& Statement::bind(int index, int64_t value) {
  sqlite3_bind_int64(statement_, index, value);
  return *this;
}
Statement& Statement::bind(int index, double value) {
  sqlite3_bind_double(statement_, index, value);
  return *this;
}
Statement& Statement::bind(int index, std::string_view text) {
  sqlite3_bind_text(statement_, index, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT);
  return *this;
}
Statement& Statement::bind_null(int index) {
  sqlite3_bind_null(statement_, index);
  return *this;
}

bool Statement::step() {
  int status = sqlite3_step(statement_);
  if (status == SQLITE_ROW) return true;
  if (status == SQLITE_DONE) return false;
  db_.fail(status, "query failed");
}

void Statement::run() {
  while (step()) {
  }
}

int Statement::column_count() const { return sqlite3_column_count(statement_); }
std::string Statement::column_name(int column) const { return sqlite3_column_name(statement_, column); }
Statement::ColumnType Statement::column_type(int column) const {
  switch (sqlite3_column_type(statement_, column)) {
    case SQLITE_INTEGER: return ColumnType::Integer;
    case SQLITE_FLOAT: return ColumnType::Real;
    case SQLITE_TEXT: return ColumnType::Text;
    case SQLITE_BLOB: return ColumnType::Blob;
    default: return ColumnType::Null;
  }
}

int64_t Statement::integer(int column) const { return sqlite3_column_int64(statement_, column); }
double Statement::real(int column) const { return sqlite3_column_double(statement_, column); }
bool Statement::is_null(int column) const { return sqlite3_column_type(statement_, column) == SQLITE_NULL; }
std::string Statement::text(int column) const {
  const auto* bytes = sqlite3_column_text(statement_, column);
  return bytes ? std::string(reinterpret_cast<const char*>(bytes), sqlite3_column_bytes(statement_, column))
               : std::string();
}

Transaction::Transaction(Database& db, TransactionKind kind) : db_(db) {
  // The busy handler already waits kBusyTimeoutMs; BEGIN IMMEDIATE can still report BUSY at
  // once in WAL mode when a snapshot must be upgraded, so retry a few times with a pause.
  const char* sql = kind == TransactionKind::Immediate ? "BEGIN IMMEDIATE" : "BEGIN DEFERRED";
  for (int attempt = 0;; ++attempt) {
    int status = sqlite3_exec(db.handle(), sql, nullptr, nullptr, nullptr);
    if (status == SQLITE_OK) return;
    if ((status & 0xFF) != SQLITE_BUSY || attempt == 50) db.fail(status, "cannot begin a transaction");
    std::this_thread::sleep_for(std::chrono::milliseconds(20 + 10 * attempt));
  }
}

Transaction::~Transaction() {
  if (open_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  assert(open_ && "transaction committed twice");
  for (int attempt = 0;; ++attempt) {
    int status = sqlite3_exec(db_.handle(), "COMMIT", nullptr, nullptr, nullptr);
    if (status == SQLITE_OK) break;
    if ((status & 0xFF) != SQLITE_BUSY || attempt == 50) db_.fail(status, "cannot commit");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  open_ = false;
}

}  // namespace maxillo::sqlite
