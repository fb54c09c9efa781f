#pragma once
// The SQLite engine of the archive index (index_connection.h), private to the archive module.
// - Database: one connection to the index file, busy timeout, extended result codes.
// - Immediate transactions are BEGIN IMMEDIATE, retried while another process writes.
// Errors become maxillo::Error(kDatabase, kArchiveBusy or kIndexDamaged) naming the file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "archive/index_connection.h"

struct sqlite3;

namespace maxillo::sqlite {

// How a connection opens its file: Create makes a missing file; Existing refuses one (a lost
// index must never be silently re-created, see archive_health.h).
enum class OpenKind { Create, Existing, ReadOnly };

class Database final : public db::Connection {
 public:
  explicit Database(const std::filesystem::path& file, OpenKind kind = OpenKind::Create);
  ~Database() override;
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  db::Engine engine() const override { return db::Engine::Sqlite; }
  const std::string& name() const override { return name_; }
  void execute(std::string_view sql) override;
  std::unique_ptr<db::PreparedStatement> prepare(std::string_view sql) override;
  void begin(db::TransactionKind kind) override;
  void commit() override;
  void rollback() noexcept override;
  // PRAGMA user_version.
  int schema_version() override;
  void set_schema_version(int version) override;
  int64_t clock_seconds() override;

  const std::filesystem::path& file() const { return file_; }
  sqlite3* handle() const { return db_; }
  [[noreturn]] void fail(int status, std::string_view what) const;

 private:
  std::filesystem::path file_;
  std::string name_;
  sqlite3* db_ = nullptr;
};

}  // namespace maxillo::sqlite
