#include "archive/index_comparison.h"

#include "archive/journal_replay.h"
#include "archive/journalled_transaction.h"

namespace maxillo {
namespace {

constexpr int kExamples = 3;

// Rows of `from` that `other` does not hold identically (SQL EXCEPT compares whole rows).
int64_t rows_missing_from(sqlite::Database& db, const std::string& table, const std::string& from,
                          const std::string& other, const std::string& label, std::vector<std::string>& examples) {
  const std::string except = "SELECT * FROM " + from + "." + table + " EXCEPT SELECT * FROM " + other + "." + table;
  sqlite::Statement count(db, "SELECT COUNT(*) FROM (" + except + ")");
  count.step();
  const int64_t rows = count.integer(0);
  sqlite::Statement sample(db, except + " LIMIT " + std::to_string(kExamples));
  while (sample.step()) {
    std::string row;
    for (int c = 0; c < sample.column_count(); ++c) row += (c ? ", " : "") + sample.column_name(c) + "=" + sample.text(c);
    examples.push_back(label + ": " + row);
  }
  return rows;
}

}  // namespace

std::string TableDifference::describe() const {
  std::string text = table + ": " + std::to_string(only_in_first) + " rows only in the first index, " +
                     std::to_string(only_in_second) + " only in the second";
  for (const auto& example : examples) text += "\n    " + example;
  return text;
}

std::vector<TableDifference> compare_attached_indexes(sqlite::Database& db, const std::string& second_schema) {
  std::vector<TableDifference> differences;
  auto tables = index_tables();
  tables.push_back("index_state");
  for (const auto& table : tables) {
    TableDifference difference{table, 0, 0, {}};
    difference.only_in_first = rows_missing_from(db, table, "main", second_schema, "only in the first", difference.examples);
    difference.only_in_second =
        rows_missing_from(db, table, second_schema, "main", "only in the second", difference.examples);
    if (difference.only_in_first || difference.only_in_second) differences.push_back(std::move(difference));
  }
  return differences;
}

std::vector<TableDifference> compare_index_files(const std::filesystem::path& first, const std::filesystem::path& second) {
  sqlite::Database db(first, sqlite::OpenKind::ReadOnly);
  sqlite::Statement attach(db, "ATTACH DATABASE ?1 AS second");
  attach.bind(1, second.string()).run();
  return compare_attached_indexes(db, "second");
}

}  // namespace maxillo
