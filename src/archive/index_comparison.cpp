#include "archive/index_comparison.h"

#include <unordered_map>

#include "archive/journal_replay.h"
#include "archive/journalled_transaction.h"
#include "core/sha256.h"

namespace maxillo {
namespace {

constexpr int kExamples = 3;

// Rows of `from` that `other` does not hold identically (SQL EXCEPT compares whole rows).
int64_t rows_missing_from(sqlite::Database& db, const std::string& table, const std::string& from,
                          const std::string& other, const std::string& label, std::vector<std::string>& examples) {
  const std::string except = "SELECT * FROM " + from + "." + table + " EXCEPT SELECT * FROM " + other + "." + table;
  db::Statement count(db, "SELECT COUNT(*) FROM (" + except + ")");
  count.step();
  const int64_t rows = count.integer(0);
  db::Statement sample(db, except + " LIMIT " + std::to_string(kExamples));
  while (sample.step()) {
    std::string row;
    for (int c = 0; c < sample.column_count(); ++c)
      row += (c ? ", " : "") + sample.column_name(c) + "=" + sample.text(c);
    examples.push_back(label + ": " + row);
  }
  return rows;
}

std::vector<std::string> compared_tables() {
  auto tables = index_tables();
  tables.push_back("index_state");
  return tables;
}

// Calls visit(json text) for every row of the table.
template <typename Visit>
void for_each_row(db::Connection& db, const std::string& table, Visit visit) {
  db::Statement rows(db, "SELECT * FROM " + table);
  while (rows.step()) visit(row_json(rows).dump());
}

TableDifference compare_table(db::Connection& first, db::Connection& second, const std::string& table) {
  TableDifference difference{table, 0, 0, {}};
  std::unordered_map<std::string, int64_t> unmatched;  // digest of a row of the first -> copies
  for_each_row(first, table, [&](const std::string& row) { ++unmatched[sha256_hex(row)]; });
  for_each_row(second, table, [&](const std::string& row) {
    auto found = unmatched.find(sha256_hex(row));
    if (found != unmatched.end() && found->second > 0) {
      --found->second;
      return;
    }
    if (++difference.only_in_second <= kExamples) difference.examples.push_back("only in the second: " + row);
  });
  for (const auto& [digest, copies] : unmatched) difference.only_in_first += copies;
  if (difference.only_in_first > 0) {
    int shown = 0;
    for_each_row(first, table, [&](const std::string& row) {
      auto found = unmatched.find(sha256_hex(row));
      if (found == unmatched.end() || found->second == 0 || shown == kExamples) return;
      --found->second;
      ++shown;
      difference.examples.push_back("only in the first: " + row);
    });
  }
  return difference;
}

}  // namespace

std::vector<TableDifference> compare_indexes(db::Connection& first, db::Connection& second) {
  std::vector<TableDifference> differences;
  for (const auto& table : compared_tables()) {
    auto difference = compare_table(first, second, table);
    if (difference.only_in_first || difference.only_in_second) differences.push_back(std::move(difference));
  }
  return differences;
}

std::string TableDifference::describe() const {
  std::string text = table + ": " + std::to_string(only_in_first) + " rows only in the first index, " +
                     std::to_string(only_in_second) + " only in the second";
  for (const auto& example : examples) text += "\n    " + example;
  return text;
}

std::vector<TableDifference> compare_attached_indexes(sqlite::Database& db, const std::string& second_schema) {
  std::vector<TableDifference> differences;
  for (const auto& table : compared_tables()) {
    TableDifference difference{table, 0, 0, {}};
    difference.only_in_first =
        rows_missing_from(db, table, "main", second_schema, "only in the first", difference.examples);
    difference.only_in_second =
        rows_missing_from(db, table, second_schema, "main", "only in the second", difference.examples);
    if (difference.only_in_first || difference.only_in_second) differences.push_back(std::move(difference));
  }
  return differences;
}

std::vector<TableDifference> compare_index_files(const std::filesystem::path& first,
                                                 const std::filesystem::path& second) {
  sqlite::Database db(first, sqlite::OpenKind::ReadOnly);
  db::Statement attach(db, "ATTACH DATABASE ?1 AS second");
  attach.bind(1, second.string()).run();
  return compare_attached_indexes(db, "second");
}

}  // namespace maxillo
