#pragma once
// A thin RAII layer over SQLite, private to the archive module (no other module sees it).
// - Database: one connection, WAL, busy timeout, foreign keys on.
// - Statement: a prepared statement, reset and re-bound for each use.
// - Transaction: BEGIN IMMEDIATE (retried while another process writes); rolls back in its
//   destructor unless commit() was called, as in Orthanc's SQLite/Transaction.
// Errors become maxillo::Error(kDatabase or kArchiveBusy) naming the database file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace maxillo::sqlite {

// How a connection opens its file: Create makes a missing file; Existing refuses one (a lost
// index must never be silently re-created, see archive_health.h).
enum class OpenKind { Create, Existing, ReadOnly };

class Database {
 public:
  explicit Database(const std::filesystem::path& file, OpenKind kind = OpenKind::Create);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  // Runs one or more statements without results (schema scripts, PRAGMAs).
  void execute(std::string_view sql);
  int user_version();
  int64_t last_insert_id() const;
  int changes() const;
  const std::filesystem::path& file() const { return file_; }
  sqlite3* handle() const { return db_; }
  [[noreturn]] void fail(int status, std::string_view what) const;

 private:
  std::filesystem::path file_;
  sqlite3* db_ = nullptr;
};

class Statement {
 public:
  Statement(Database& db, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  // Resets the statement and clears bindings; call before binding a new use.
  Statement& reset();
  // Parameters are 1-based, as in SQLite.
  Statement& bind(int index, int64_t value);
  Statement& bind(int index, int value) { return bind(index, int64_t(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, const std::string& text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind_null(int index);
  Statement& bind(int index, std::optional<double> value) { return value ? bind(index, *value) : bind_null(index); }

  // Advances to the next row: true if there is one, false when done.
  bool step();
  // Runs a statement that returns no rows.
  void run();

  enum class ColumnType { Integer, Real, Text, Blob, Null };
  int column_count() const;
  std::string column_name(int column) const;
  ColumnType column_type(int column) const;

  int64_t integer(int column) const;
  double real(int column) const;
  std::string text(int column) const;
  bool is_null(int column) const;

 private:
  Database& db_;
  sqlite3_stmt* statement_ = nullptr;
};

enum class TransactionKind { Immediate, Deferred };

class Transaction {
 public:
  explicit Transaction(Database& db, TransactionKind kind = TransactionKind::Immediate);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database& db_;
  bool open_ = true;
};

}  // namespace maxillo::sqlite
