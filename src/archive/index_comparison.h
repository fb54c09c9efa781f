#pragma once
// Row-by-row comparison of two archive indexes (the same schema): every table of
// index_tables() plus the journal counter, rows compared whole (ids included).
#include <filesystem>
#include <string>
#include <vector>

#include "archive/index_connection.h"
#include "archive/sqlite.h"

namespace maxillo {

struct TableDifference {
  std::string table;
  int64_t only_in_first = 0;  // rows of the first index the second lacks (or holds otherwise)
  int64_t only_in_second = 0;
  std::vector<std::string> examples;  // up to a few rows, "only in first: {json}"
  std::string describe() const;
};

// Any two indexes, on any engines (a server index and the replay of its journal, an embedded
// index and the server index it was migrated into): rows are compared as their JSON text
// (journalled_transaction.h's row_as_json), by digest, so memory grows by 32 bytes a row.
std::vector<TableDifference> compare_indexes(db::Connection& first, db::Connection& second);

// Two SQLite indexes, in SQL: `db` holds the first as "main" and the second attached under
// `second_schema`.
std::vector<TableDifference> compare_attached_indexes(sqlite::Database& db, const std::string& second_schema);

// Opens both files (read only) and compares them.
std::vector<TableDifference> compare_index_files(const std::filesystem::path& first,
                                                 const std::filesystem::path& second);

}  // namespace maxillo
