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
// index must never be silently re-created, see archive_health.h). ReadOnlyUntouched reads a
// file that nothing writes meanwhile (the caller holds its archive's store lock exclusively)
// and leaves nothing beside it: a plain read-only connection to a WAL index creates its -wal
// and -shm files, which `archive migrate` left in the source it promises not to change. With no
// WAL beside the file, SQLite is told the file is immutable; with one, its files are used.
enum class OpenKind { Create, Existing, ReadOnly, ReadOnlyUntouched };

class Database final : public db::Connection {
 public:
  explicit Database(const std::filesystem::path& file, OpenKind kind = OpenKind::Create);
  ~Database() override;
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

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

  // The settings every connection to an archive index uses: WAL, synchronous=NORMAL, foreign
  // keys, page checks. Kept when the connection is opened again.
  void use_archive_settings();
  // The file at this path was replaced (`archive rebuild-index` renames a new index in): this
  // connection is opened again on the file now there. SQLite's SQLITE_FCNTL_HAS_MOVED compares
  // the open file's inode with the path's.
  bool reopen_if_moved() override;
  std::filesystem::path index_file() const override { return file_; }
  void make_read_only() override;  // PRAGMA query_only
  std::string quick_check() override;
  std::string integrity_check() override;
  std::vector<std::string> table_columns(const std::string& table) override;

  const std::filesystem::path& file() const { return file_; }
  sqlite3* handle() const { return db_; }
  [[noreturn]] void fail(int status, std::string_view what) const;

 private:
  void open();

  std::filesystem::path file_;
  std::string name_;
  OpenKind kind_;
  bool archive_settings_ = false;
  sqlite3* db_ = nullptr;
};

}  // namespace maxillo::sqlite
