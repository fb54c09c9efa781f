#include "archive/journalled_transaction.h"

#include "archive/archive_state.h"
#include "core/version.h"

namespace maxillo {
namespace {

Json column_value(const sqlite::Statement& row, int column) {
  switch (row.column_type(column)) {
    case sqlite::Statement::ColumnType::Integer: return row.integer(column);
    case sqlite::Statement::ColumnType::Real: return row.real(column);
    case sqlite::Statement::ColumnType::Null: return nullptr;
    default: return row.text(column);  // the schema stores no blobs
  }
}

Json current_row(const sqlite::Statement& row) {
  Json values = Json::object();
  for (int column = 0; column < row.column_count(); ++column) values[row.column_name(column)] = column_value(row, column);
  return values;
}

}  // namespace

Json row_as_json(sqlite::Database& db, std::string_view table, std::string_view where, const std::vector<SqlKey>& keys) {
  sqlite::Statement query(db, "SELECT * FROM " + std::string(table) + " WHERE " + std::string(where));
  for (size_t k = 0; k < keys.size(); ++k)
    std::visit([&](const auto& key) { query.bind(int(k + 1), key); }, keys[k]);
  if (!query.step()) throw Error(ErrorCode::kDatabase, db.file().string(), "journal: no row in " + std::string(table));
  return current_row(query);
}

int64_t journal_sequence(sqlite::Database& db) {
  sqlite::Statement query(db, "SELECT journal_sequence FROM index_state WHERE id = 1");
  return query.step() ? query.integer(0) : 0;
}

JournalledTransaction::JournalledTransaction(sqlite::Database& db, const IndexJournal& journal, std::string operation)
    : db_(db), journal_(journal), transaction_(db) {
  entry_.operation = std::move(operation);
}

void JournalledTransaction::inserted(std::string_view table, int64_t rowid) {
  entry_.rows.push_back({std::string(table), row_as_json(db_, table, "rowid = ?1", {rowid})});
}

void JournalledTransaction::written(std::string_view table, std::string_view where, const std::vector<SqlKey>& keys) {
  entry_.rows.push_back({std::string(table), row_as_json(db_, table, where, keys)});
}

void JournalledTransaction::all_rows_of(std::string_view table) {
  sqlite::Statement query(db_, "SELECT * FROM " + std::string(table));
  while (query.step()) entry_.rows.push_back({std::string(table), current_row(query)});
}

void JournalledTransaction::commit() {
  if (!entry_.rows.empty()) {
    // Under the write lock taken by BEGIN IMMEDIATE: the counter gives commit order.
    sqlite::Statement next(db_, "UPDATE index_state SET journal_sequence = journal_sequence + 1 WHERE id = 1 "
                                "RETURNING journal_sequence");
    if (!next.step()) throw Error(ErrorCode::kIndexDamaged, db_.file().string(), "index_state row missing");
    entry_.sequence = next.integer(0);
    next.run();
    entry_.at = utc_now();
    entry_.program_version = kVersion;
    journal_.write(entry_);
  }
  transaction_.commit();
}

}  // namespace maxillo
