#include "archive/postgres.h"

#include <libpq-fe.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "archive/archive_location.h"
#include "core/error.h"
#include "core/utf8.h"

namespace maxillo::postgres {
namespace {

// SQLSTATE classes (PostgreSQL appendix A) that decide how a failure is reported.
ErrorCode code_for(const char* sqlstate) {
  const std::string_view state = sqlstate ? sqlstate : "";
  if (state == "40001" || state == "40P01" || state == "23505" || state == "55P03") return ErrorCode::kArchiveBusy;
  if (state.starts_with("08") || state == "57P01" || state == "57P02" || state == "57P03")
    return ErrorCode::kArchiveUnreachable;
  if (state == "XX001" || state == "XX002") return ErrorCode::kIndexDamaged;
  return ErrorCode::kDatabase;
}

std::string server_name(pg_conn* connection) {
  std::string host = PQhost(connection) ? PQhost(connection) : "";
  return "postgresql://" + std::string(PQuser(connection)) + "@" + host + ":" + PQport(connection) + "/" +
         PQdb(connection);
}

// libpq's messages end in a newline.
std::string without_trailing_space(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

void ignore_notice(void*, const char*) {}  // "relation already exists, skipping" and the like

class Result {
 public:
  explicit Result(PGresult* result) : result_(result) {}
  ~Result() { PQclear(result_); }
  Result(const Result&) = delete;
  Result& operator=(const Result&) = delete;
  PGresult* get() const { return result_; }
  bool ok() const {
    auto status = PQresultStatus(result_);
    return status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK;
  }

 private:
  PGresult* result_;
};

class PostgresStatement final : public db::PreparedStatement {
 public:
  PostgresStatement(Connection& connection, std::string name, int parameters)
      : connection_(connection), name_(std::move(name)), values_(size_t(parameters)) {}
  ~PostgresStatement() override { PQclear(result_); }

  void reset() override {
    PQclear(result_);
    result_ = nullptr;
    row_ = -1;
    for (auto& value : values_) value.reset();
  }
  void bind_integer(int index, int64_t value) override { value_at(index) = std::to_string(value); }
  void bind_real(int index, double value) override {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);  // round-trips every double
    value_at(index) = text;
  }
  // PostgreSQL's text must be UTF-8 without NUL; the index keeps bytes (core/utf8.h).
  void bind_text(int index, std::string_view text) override { value_at(index) = bytes_as_utf8(text); }
  void bind_null(int index) override { value_at(index).reset(); }

  bool step() override {
    if (!result_) run();
    return ++row_ < PQntuples(result_);
  }
  int rows_changed() const override {
    const char* count = result_ ? PQcmdTuples(result_) : "";
    return *count ? std::atoi(count) : 0;
  }

  int column_count() const override { return PQnfields(result_); }
  std::string column_name(int column) const override { return PQfname(result_, column); }
  db::ColumnType column_type(int column) const override {
    if (PQgetisnull(result_, row_, column)) return db::ColumnType::Null;
    switch (PQftype(result_, column)) {  // pg_type OIDs
      case 20:
      case 21:
      case 23:
      case 26: return db::ColumnType::Integer;  // int8, int2, int4, oid
      case 700:
      case 701:
      case 1700: return db::ColumnType::Real;  // float4, float8, numeric
      default: return db::ColumnType::Text;
    }
  }
  int64_t integer(int column) const override { return std::strtoll(PQgetvalue(result_, row_, column), nullptr, 10); }
  double real(int column) const override { return std::strtod(PQgetvalue(result_, row_, column), nullptr); }
  std::string text(int column) const override {
    return bytes_from_utf8(
        std::string_view(PQgetvalue(result_, row_, column), size_t(PQgetlength(result_, row_, column))));
  }

 private:
  std::optional<std::string>& value_at(int index) {
    if (index < 1 || size_t(index) > values_.size())
      throw Error(ErrorCode::kDatabase, connection_.name(), "parameter ?" + std::to_string(index) + " out of range");
    return values_[size_t(index - 1)];
  }
  void run() {
    std::vector<const char*> pointers;
    for (const auto& value : values_) pointers.push_back(value ? value->c_str() : nullptr);
    result_ =
        PQexecPrepared(connection_.handle(), name_.c_str(), int(pointers.size()), pointers.data(), nullptr, nullptr, 0);
    auto status = PQresultStatus(result_);
    if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) {
      PGresult* failed = result_;
      result_ = nullptr;
      Result owner(failed);
      connection_.fail(failed, "query failed");
    }
    row_ = -1;
  }

  Connection& connection_;
  std::string name_;
  std::vector<std::optional<std::string>> values_;
  PGresult* result_ = nullptr;
  int row_ = -1;
};

int highest_parameter(std::string_view numbered) {
  int highest = 0;
  for (size_t at = numbered.find('$'); at != std::string_view::npos; at = numbered.find('$', at + 1))
    highest = std::max(highest, std::atoi(std::string(numbered.substr(at + 1, 6)).c_str()));
  return highest;
}

}  // namespace

std::string numbered_parameters(std::string_view sql) {
  std::string out;
  out.reserve(sql.size());
  char quote = 0;
  for (char c : sql) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '?') {
      c = '$';
    }
    out += c;
  }
  return out;
}

Connection::Connection(const std::string& uri) : name_(without_password(uri)) {
  connection_ = PQconnectdb(uri.c_str());
  if (PQstatus(connection_) != CONNECTION_OK) {
    const std::string reason = connection_ ? without_trailing_space(PQerrorMessage(connection_)) : "out of memory";
    PQfinish(connection_);
    connection_ = nullptr;
    // The server answered and refused (a wrong password, an unknown role or database, no
    // pg_hba.conf entry): libpq reports its FATAL message. That is not an unreachable server.
    if (reason.find("FATAL:") != std::string::npos)
      throw Error(ErrorCode::kArchiveLoginRefused, name_,
                  "the archive's index server refused the connection: " + reason);
    throw Error(ErrorCode::kArchiveUnreachable, name_, "cannot connect to the archive's index server: " + reason);
  }
  name_ = server_name(connection_);
  PQsetNoticeProcessor(connection_, ignore_notice, nullptr);
  execute("SET client_min_messages = warning");
}

Connection::~Connection() { PQfinish(connection_); }

void Connection::fail(const void* failed, std::string_view what) const {
  const auto* result = static_cast<const PGresult*>(failed);
  const char* sqlstate = result ? PQresultErrorField(result, PG_DIAG_SQLSTATE) : nullptr;
  const std::string reason = without_trailing_space(
      result && *PQresultErrorMessage(result) ? PQresultErrorMessage(result) : PQerrorMessage(connection_));
  // A dropped connection has no SQLSTATE: it is the server that went away.
  ErrorCode code = PQstatus(connection_) == CONNECTION_BAD ? ErrorCode::kArchiveUnreachable : code_for(sqlstate);
  throw Error(code, name_, std::string(what) + ": " + reason);
}

void Connection::execute(std::string_view sql) {
  Result result(PQexec(connection_, std::string(sql).c_str()));
  if (!result.ok()) fail(result.get(), "statement failed");
}

std::unique_ptr<db::PreparedStatement> Connection::prepare(std::string_view sql) {
  auto known = prepared_.find(sql);
  if (known == prepared_.end()) {  // once per connection and SQL text; every later use is a lookup
    const std::string numbered = numbered_parameters(sql);
    Prepared statement{"maxillo_" + std::to_string(prepared_.size() + 1), highest_parameter(numbered)};
    Result result(PQprepare(connection_, statement.name.c_str(), numbered.c_str(), 0, nullptr));
    if (!result.ok()) fail(result.get(), "cannot prepare \"" + std::string(sql.substr(0, 60)) + "\"");
    known = prepared_.emplace(std::string(sql), std::move(statement)).first;
  }
  return std::make_unique<PostgresStatement>(*this, known->second.name, known->second.parameters);
}

void Connection::begin(db::TransactionKind kind) {
  execute("BEGIN ISOLATION LEVEL READ COMMITTED");
  // Writers (Immediate) lock the rows they write and no more; only a migration takes the
  // whole index (db::TransactionKind).
  if (kind == db::TransactionKind::Exclusive) {
    try {
      execute("SELECT pg_advisory_xact_lock(" + std::to_string(kMigrationLockKey) + ")");
    } catch (...) {
      rollback();
      throw;
    }
  }
}

void Connection::commit() { execute("COMMIT"); }

void Connection::rollback() noexcept { PQclear(PQexec(connection_, "ROLLBACK")); }

int Connection::schema_version() {
  db::Statement exists(
      *this, "SELECT COUNT(*) FROM pg_tables WHERE schemaname = current_schema() AND tablename = 'maxillo_schema'");
  if (db::single_integer(exists) == 0) return 0;
  db::Statement version(*this, "SELECT version FROM maxillo_schema");
  return int(db::single_integer(version));
}

void Connection::set_schema_version(int version) {
  execute(
      "CREATE TABLE IF NOT EXISTS maxillo_schema (version INTEGER NOT NULL); DELETE FROM maxillo_schema; "
      "INSERT INTO maxillo_schema(version) VALUES (" +
      std::to_string(version) + ")");
}

int64_t Connection::clock_seconds() {
  // clock_timestamp(), not now(): now() stays at the start of an open transaction.
  db::Statement query(*this, "SELECT CAST(FLOOR(EXTRACT(EPOCH FROM clock_timestamp())) AS BIGINT)");
  return db::single_integer(query);
}

void Connection::lock(int64_t key, bool shared) {
  execute(std::string(shared ? "SELECT pg_advisory_lock_shared(" : "SELECT pg_advisory_lock(") + std::to_string(key) +
          ")");
}

bool Connection::try_lock(int64_t key, bool shared) {
  db::Statement attempt(*this,
                        std::string(shared ? "SELECT pg_try_advisory_lock_shared(" : "SELECT pg_try_advisory_lock(") +
                            std::to_string(key) + ")");
  return attempt.step() && attempt.text(0) == "t";
}

void Connection::unlock(int64_t key, bool shared) noexcept {
  std::string sql = std::string(shared ? "SELECT pg_advisory_unlock_shared(" : "SELECT pg_advisory_unlock(") +
                    std::to_string(key) + ")";
  PQclear(PQexec(connection_, sql.c_str()));
}

void Connection::make_read_only() { execute("SET default_transaction_read_only = on"); }

std::vector<std::string> Connection::table_columns(const std::string& table) {
  db::Statement info(*this,
                     "SELECT column_name FROM information_schema.columns WHERE table_name = ?1 "
                     "AND table_schema = current_schema() ORDER BY ordinal_position");
  info.bind(1, table);
  std::vector<std::string> columns;
  while (info.step()) columns.push_back(info.text(0));
  return columns;
}

void Connection::advance_identity(const std::string& table) {
  execute("SELECT setval(pg_get_serial_sequence('" + table + "', 'id'), COALESCE((SELECT MAX(id) FROM " + table +
          "), 0) + 1, false)");
}

}  // namespace maxillo::postgres
