#pragma once
// A connection to an archive index, whichever engine holds it: the embedded SQLite file
// (sqlite.h) or a PostgreSQL server (postgres.h). Private to the archive module.
//
// The archive's statements are written once, in the SQL both engines accept (archive_sql.h):
// positional parameters ?1, ?2... (the PostgreSQL driver renumbers them $1, $2...), ON CONFLICT
// instead of INSERT OR IGNORE, RETURNING id instead of a last-insert-rowid call, COALESCE and
// CAST instead of engine functions. Where the engines truly differ (the schema's DDL, schema
// version, integrity checks, read-only sessions, claiming work, identities) the connection
// answers for its engine: nothing outside sqlite.* and postgres.* asks which engine it is.
//
//   db::Statement insert(connection, "INSERT INTO t(a) VALUES (?1) RETURNING id");
//   insert.reset().bind(1, "x");
//   if (insert.step()) id = insert.integer(0);
//
// Errors are maxillo::Error naming the index (file or server): kArchiveBusy for what a retry
// of the whole transaction may cure (busy, serialization failure, deadlock, unique violation),
// kIndexDamaged for a damaged index, kDatabase otherwise.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace maxillo::db {

enum class ColumnType { Integer, Real, Text, Null };
// Immediate: a writer. SQLite takes its single write lock at once (BEGIN IMMEDIATE), so
// writers run one after another. PostgreSQL locks only the rows written (unique keys with ON
// CONFLICT make the same row arriving twice one row), so writers run side by side; they meet
// only on the journal counter's row, taken last, just before COMMIT (journalled_transaction.h),
// which orders the commits as the journal numbers them.
// Exclusive: the whole index for this transaction alone on every engine (SQLite BEGIN
// IMMEDIATE, a transaction-scoped advisory lock on PostgreSQL): schema migrations, so that of
// two nodes starting at once one migrates and the other finds the work done.
// Deferred: a reader's consistent view.
enum class TransactionKind { Immediate, Deferred, Exclusive };

// One prepared statement of an engine; used through db::Statement.
class PreparedStatement {
 public:
  virtual ~PreparedStatement() = default;
  virtual void reset() = 0;  // forgets results and bindings
  virtual void bind_integer(int index, int64_t value) = 0;
  virtual void bind_real(int index, double value) = 0;
  virtual void bind_text(int index, std::string_view text) = 0;
  virtual void bind_null(int index) = 0;
  virtual bool step() = 0;               // the first call runs the statement
  virtual int rows_changed() const = 0;  // by the last run of an INSERT, UPDATE or DELETE
  virtual int column_count() const = 0;
  virtual std::string column_name(int column) const = 0;
  virtual ColumnType column_type(int column) const = 0;
  virtual int64_t integer(int column) const = 0;
  virtual double real(int column) const = 0;
  virtual std::string text(int column) const = 0;
};

class Connection {
 public:
  virtual ~Connection() = default;
  // What error messages name: the index file, or the server without its password.
  virtual const std::string& name() const = 0;
  // Runs one or more statements without results (schema scripts).
  virtual void execute(std::string_view sql) = 0;
  virtual std::unique_ptr<PreparedStatement> prepare(std::string_view sql) = 0;
  virtual void begin(TransactionKind kind) = 0;
  virtual void commit() = 0;
  virtual void rollback() noexcept = 0;
  // The schema version the index records (0 for an empty index), and setting it inside the
  // migration's transaction.
  virtual int schema_version() = 0;
  virtual void set_schema_version(int version) = 0;
  // The index's clock in Unix seconds: the server's on PostgreSQL, so that a lease means the
  // same on every node whatever their own clocks say; this machine's for an embedded file.
  virtual int64_t clock_seconds() = 0;
  // Whether the index this connection reads was replaced since it was opened (an embedded
  // index file swapped by `archive rebuild-index`), in which case the connection is opened
  // again on the new one. A server's database is never swapped under a connection.
  virtual bool reopen_if_moved() { return false; }

  // Where the engines differ.
  // The index file of an embedded index (empty for a server's database): what a damaged index
  // is rebuilt beside.
  virtual std::filesystem::path index_file() const { return {}; }
  // The folder under db/ holding this engine's own versions of migrations (empty: the shared
  // SQL serves).
  virtual std::string migration_dialect() const { return {}; }
  // No statement of this session may write from now on.
  virtual void make_read_only() = 0;
  // Whether a transaction can lock the single rows it picks and let others skip them (SELECT
  // ... FOR UPDATE SKIP LOCKED); else writers serialise on the whole index (BEGIN IMMEDIATE).
  virtual bool locks_rows() const { return false; }
  // A quick check of the index's pages ("ok", or the first finding), and a full one (up to
  // 20 findings joined by "; "). "ok" for a server, which checks its pages as it reads them.
  virtual std::string quick_check() { return "ok"; }
  virtual std::string integrity_check() { return "ok"; }
  // The columns of an index table, in their order.
  virtual std::vector<std::string> table_columns(const std::string& table) = 0;
  // After rows were written with their own ids: the table's next generated id moves past them.
  virtual void advance_identity(const std::string& /*table*/) {}
};

// A prepared statement, reset and re-bound for each use.
class Statement {
 public:
  Statement(Connection& connection, std::string_view sql) : prepared_(connection.prepare(sql)) {}

  Statement& reset() {
    prepared_->reset();
    return *this;
  }
  // Parameters are 1-based.
  Statement& bind(int index, int64_t value) {
    prepared_->bind_integer(index, value);
    return *this;
  }
  Statement& bind(int index, int value) { return bind(index, int64_t(value)); }
  Statement& bind(int index, double value) {
    prepared_->bind_real(index, value);
    return *this;
  }
  Statement& bind(int index, std::string_view text) {
    prepared_->bind_text(index, text);
    return *this;
  }
  Statement& bind(int index, const std::string& text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind_null(int index) {
    prepared_->bind_null(index);
    return *this;
  }
  Statement& bind(int index, std::optional<double> value) { return value ? bind(index, *value) : bind_null(index); }
  Statement& bind(int index, std::optional<int> value) { return value ? bind(index, *value) : bind_null(index); }

  // Advances to the next row: true if there is one, false when done.
  bool step() { return prepared_->step(); }
  // Runs a statement to its end; returns the rows it inserted, updated or deleted.
  int run() {
    while (prepared_->step()) {}
    return prepared_->rows_changed();
  }

  int column_count() const { return prepared_->column_count(); }
  std::string column_name(int column) const { return prepared_->column_name(column); }
  ColumnType column_type(int column) const { return prepared_->column_type(column); }
  int64_t integer(int column) const { return prepared_->integer(column); }
  double real(int column) const { return prepared_->real(column); }
  std::string text(int column) const { return prepared_->text(column); }
  bool is_null(int column) const { return prepared_->column_type(column) == ColumnType::Null; }

 private:
  std::unique_ptr<PreparedStatement> prepared_;
};

// Rolls back in its destructor unless commit() was called, as in Orthanc's SQLite/Transaction.
class Transaction {
 public:
  explicit Transaction(Connection& connection, TransactionKind kind = TransactionKind::Immediate)
      : connection_(connection) {
    connection_.begin(kind);
  }
  ~Transaction() {
    if (open_) connection_.rollback();
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit() {
    connection_.commit();
    open_ = false;
  }

 private:
  Connection& connection_;
  bool open_ = true;
};

// The first column of the first row, or `otherwise` when there is no row. Resets the query.
int64_t single_integer(Statement& query, int64_t otherwise = 0);

// Runs an INSERT ... RETURNING id: the new row's id, or nothing when no row was made (ON
// CONFLICT DO NOTHING met an existing one). Resets the statement.
std::optional<int64_t> inserted_id(Statement& insert);

// Runs `body` (which opens and commits its own transaction) again when it fails with
// kArchiveBusy: a serialization failure, deadlock or unique violation between concurrent
// writers on PostgreSQL, a busy SQLite file. The whole transaction is retried, never a part,
// as Orthanc's PostgreSQL plugin and dcm4chee do. `body` must start from scratch each time.
void retry_transaction(const std::function<void()>& body);

// "(?1, ?2), (?3, ?4)" for rows = 2, columns = 2: the VALUES of a multi-row INSERT, one
// round trip for many rows (both engines take such a list; keep rows x columns under 32766).
std::string value_rows(int rows, int columns);

// Runs `before + "?1, ?2, ..." + after`, an IN list of `ids`, and calls `row` on every result
// row: many cases or series in a few round trips instead of one per id (on a server each costs
// a network round trip). Ids are deduplicated and split into chunks of at most 4096 (a server
// scans a large table once per chunk; SQLite takes up to 32766 parameters), each padded to 1, 8,
// 64, 512 or 4096 places by repeating its last id (a repeated id in an IN list changes nothing),
// so a server prepares at most five statements per query text. Rows come in the query's order
// within a chunk; group them by id.
void for_each_row_with_ids(Connection& connection, std::string_view before, std::string_view after,
                           std::vector<int64_t> ids, const std::function<void(const Statement&)>& row);
// The same with text keys (UIDs).
void for_each_row_with_keys(Connection& connection, std::string_view before, std::string_view after,
                            std::vector<std::string> keys, const std::function<void(const Statement&)>& row);

}  // namespace maxillo::db
