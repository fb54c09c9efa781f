#pragma once
// The PostgreSQL engine of the archive index (index_connection.h) over libpq, private to the
// archive module. One connection per Archive (and one per import's scanning thread).
// - Statements are prepared once per connection and SQL text (PQprepare), executed with text
//   parameters; ?N in the shared SQL becomes $N.
// - Transactions run at READ COMMITTED. A writing (immediate) transaction locks only the rows
//   it writes, so writers from every node run side by side; they commit in journal order
//   because each takes the journal counter's row last (journalled_transaction.h). Only an
//   exclusive transaction (a schema migration) first takes a transaction-scoped advisory lock.
// - SQLSTATE decides the error: serialization failure, deadlock, unique violation and lock
//   timeouts are kArchiveBusy (retry_transaction retries the whole transaction), a lost
//   connection is kArchiveUnreachable, data corruption kIndexDamaged, the rest kDatabase.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "archive/index_connection.h"

struct pg_conn;

namespace maxillo::postgres {

// ?1, ?2... outside quoted text become $1, $2...
std::string numbered_parameters(std::string_view sql);

class Connection final : public db::Connection {
 public:
  // `uri`: a libpq connection URI or keyword string. Throws Error(kArchiveUnreachable) naming
  // the server (never its password) when it cannot connect.
  explicit Connection(const std::string& uri);
  ~Connection() override;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  const std::string& name() const override { return name_; }
  void execute(std::string_view sql) override;
  std::unique_ptr<db::PreparedStatement> prepare(std::string_view sql) override;
  void begin(db::TransactionKind kind) override;
  void commit() override;
  void rollback() noexcept override;
  // Kept in the table maxillo_schema (0 when it does not exist yet).
  int schema_version() override;
  void set_schema_version(int version) override;
  int64_t clock_seconds() override;
  std::string migration_dialect() const override { return "postgresql"; }
  void make_read_only() override;  // default_transaction_read_only
  bool locks_rows() const override { return true; }
  std::vector<std::string> table_columns(const std::string& table) override;
  // setval of the table's id sequence past its highest id.
  void advance_identity(const std::string& table) override;

  // Session-level advisory locks, released by unlock or when the connection ends (a killed
  // process's locks go with its connection).
  void lock(int64_t key, bool shared);
  // The lock if it can be had now (then held, as lock() holds it); false when another session
  // holds it in a conflicting mode.
  bool try_lock(int64_t key, bool shared);
  void unlock(int64_t key, bool shared) noexcept;

  pg_conn* handle() const { return connection_; }
  [[noreturn]] void fail(const void* result, std::string_view what) const;

 private:
  std::string name_;
  pg_conn* connection_ = nullptr;
  struct Prepared {
    std::string name;
    int parameters = 0;
  };
  std::map<std::string, Prepared, std::less<>> prepared_;  // SQL text -> its server-side statement
};

// Advisory lock keys of an archive database (any 64-bit numbers no other user of the
// database takes; these spell "maxillo" and a purpose).
inline constexpr int64_t kMigrationLockKey = 0x6d6178696c6c6f01;  // exclusive transactions
inline constexpr int64_t kStoreLockKey = 0x6d6178696c6c6f02;      // importers shared, repair exclusive

}  // namespace maxillo::postgres
