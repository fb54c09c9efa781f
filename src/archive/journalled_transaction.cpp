#include "archive/journalled_transaction.h"

#include "archive/archive_state.h"
#include "core/log.h"
#include "core/utf8.h"
#include "core/version.h"

namespace maxillo {
namespace {

Json column_value(const db::Statement& row, int column) {
  switch (row.column_type(column)) {
    case db::ColumnType::Integer: return row.integer(column);
    case db::ColumnType::Real: return row.real(column);
    case db::ColumnType::Null: return nullptr;
    default: return bytes_as_utf8(row.text(column));  // no blobs; a Latin-1 file path stays its bytes in JSON
  }
}

}  // namespace

Json row_json(const db::Statement& row) {
  Json values = Json::object();
  for (int column = 0; column < row.column_count(); ++column)
    values[row.column_name(column)] = column_value(row, column);
  return values;
}

Json row_as_json(db::Connection& db, std::string_view table, std::string_view where, const std::vector<SqlKey>& keys) {
  db::Statement query(db, "SELECT * FROM " + std::string(table) + " WHERE " + std::string(where));
  for (size_t k = 0; k < keys.size(); ++k) std::visit([&](const auto& key) { query.bind(int(k + 1), key); }, keys[k]);
  if (!query.step()) throw Error(ErrorCode::kDatabase, db.name(), "journal: no row in " + std::string(table));
  return row_json(query);
}

int64_t journal_sequence(db::Connection& db) {
  db::Statement query(db, "SELECT journal_sequence FROM index_state WHERE id = 1");
  return query.step() ? query.integer(0) : 0;
}

JournalledTransaction::JournalledTransaction(db::Connection& db, const IndexJournal& journal, std::string operation,
                                             db::TransactionKind kind)
    : db_(db), journal_(journal), transaction_(db, kind) {
  entry_.operation = std::move(operation);
}

void JournalledTransaction::inserted(std::string_view table, int64_t id) {
  entry_.rows.push_back({std::string(table), row_as_json(db_, table, "id = ?1", {id})});
}

void JournalledTransaction::inserted_row(std::string_view table, const db::Statement& row) {
  entry_.rows.push_back({std::string(table), row_json(row)});
}

void JournalledTransaction::written(std::string_view table, std::string_view where, const std::vector<SqlKey>& keys) {
  entry_.rows.push_back({std::string(table), row_as_json(db_, table, where, keys)});
}

void JournalledTransaction::all_rows_of(std::string_view table) {
  db::Statement query(db_, "SELECT * FROM " + std::string(table));
  while (query.step()) entry_.rows.push_back({std::string(table), row_json(query)});
}

void JournalledTransaction::commit() {
  if (entry_.rows.empty()) {
    transaction_.commit();
    return;
  }
  // The counter row's lock is held from here to COMMIT (SQLite: the file's write lock, held
  // since BEGIN IMMEDIATE): the writer that takes N+1 waits until N committed or rolled back,
  // so the numbers are the commit order without gaps.
  db::Statement next(db_,
                     "UPDATE index_state SET journal_sequence = journal_sequence + 1 WHERE id = 1 "
                     "RETURNING journal_sequence");
  if (!next.step()) throw Error(ErrorCode::kIndexDamaged, db_.name(), "index_state row missing");
  entry_.sequence = next.integer(0);
  next.run();
  entry_.at = utc_now();
  entry_.program_version = kVersion;
  // The entry before ours committed (the counter says so) even if its writer died before
  // marking it: mark it, so that the committed entries stay 1..N without a gap.
  if (!journal_.settle(entry_.sequence - 1))
    throw Error(ErrorCode::kWriteFailed, journal_.pending_path_of(entry_.sequence - 1).string(),
                "cannot mark this committed journal entry; nothing was written");
  journal_.write_pending(entry_);
  transaction_.commit();
  try {
    journal_.mark_committed(entry_.sequence);
  } catch (const Error& e) {
    // Committed all the same: the next writer or the next open marks it (IndexJournal::settle).
    log::warning("journal entry ", entry_.sequence, " committed but not yet marked: ", e.reason());
  }
}

}  // namespace maxillo
