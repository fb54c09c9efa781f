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
}  // namespace

Database::Database(const std::filesystem::path& file) : file_(file) {
  int status = sqlite3_open_v2(file.c_str(), &db_,
                               SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr);
  if (status != SQLITE_OK) {
    std::string reason = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(status);
    sqlite3_close(db_);
    db_ = nullptr;
    throw Error(ErrorCode::kDatabase, file.string(), "cannot open: " + reason);
  }
  sqlite3_busy_timeout(db_, kBusyTimeoutMs);
  sqlite3_extended_result_codes(db_, 1);
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::fail(int status, std::string_view what) const {
  int primary = status & 0xFF;
  ErrorCode code = (primary == SQLITE_BUSY || primary == SQLITE_LOCKED) ? ErrorCode::kArchiveBusy : ErrorCode::kDatabase;
  throw Error(code, file_.string(), std::string(what) + ": " + sqlite3_errmsg(db_));
}

void Database::execute(std::string_view sql) {
  std::string text(sql);
  char* message = nullptr;
  int status = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &message);
  if (status != SQLITE_OK) {
    std::string reason = message ? message : sqlite3_errstr(status);
    sqlite3_free(message);
    ErrorCode code = (status & 0xFF) == SQLITE_BUSY ? ErrorCode::kArchiveBusy : ErrorCode::kDatabase;
    throw Error(code, file_.string(), reason);
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
