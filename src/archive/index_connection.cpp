#include "archive/index_connection.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "core/error.h"

namespace maxillo::db {

int64_t single_integer(Statement& query, int64_t otherwise) {
  int64_t value = query.step() ? query.integer(0) : otherwise;
  query.reset();
  return value;
}

std::optional<int64_t> inserted_id(Statement& insert) {
  std::optional<int64_t> id;
  if (insert.step()) id = insert.integer(0);
  insert.reset();
  return id;
}

void retry_transaction(const std::function<void()>& body) {
  // Conflicts between writers clear within milliseconds; a few dozen attempts with a growing
  // pause outlast any of them, and a lasting problem still surfaces as kArchiveBusy.
  constexpr int kAttempts = 40;
  for (int attempt = 1;; ++attempt) {
    try {
      body();
      return;
    } catch (const Error& e) {
      if (e.code() != ErrorCode::kArchiveBusy || attempt == kAttempts) throw;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5 * attempt));
  }
}

std::string value_rows(int rows, int columns) {
  std::string sql;
  for (int row = 0, parameter = 1; row < rows; ++row) {
    sql += row > 0 ? ", (" : "(";
    for (int column = 0; column < columns; ++column, ++parameter)
      sql += (column > 0 ? ", ?" : "?") + std::to_string(parameter);
    sql += ")";
  }
  return sql;
}

namespace {

// for_each_row_with_ids and for_each_row_with_keys: the same IN lists of integers or texts.
template <class Key>
void for_each_row_in(Connection& connection, std::string_view before, std::string_view after, std::vector<Key> keys,
                     const std::function<void(const Statement&)>& row) {
  constexpr size_t kPlaces[] = {1, 8, 64, 512, 4096};
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  for (size_t first = 0; first < keys.size(); first += kPlaces[4]) {
    const size_t count = std::min(keys.size() - first, kPlaces[4]);
    const size_t places = *std::find_if(std::begin(kPlaces), std::end(kPlaces), [&](size_t n) { return n >= count; });
    std::string sql(before);
    for (size_t n = 1; n <= places; ++n) sql += (n > 1 ? ", ?" : "?") + std::to_string(n);
    sql += after;
    Statement query(connection, sql);
    for (size_t n = 0; n < places; ++n) query.bind(int(n + 1), keys[first + std::min(n, count - 1)]);
    while (query.step()) row(query);
  }
}

}  // namespace

void for_each_row_with_ids(Connection& connection, std::string_view before, std::string_view after,
                           std::vector<int64_t> ids, const std::function<void(const Statement&)>& row) {
  for_each_row_in(connection, before, after, std::move(ids), row);
}

void for_each_row_with_keys(Connection& connection, std::string_view before, std::string_view after,
                            std::vector<std::string> keys, const std::function<void(const Statement&)>& row) {
  for_each_row_in(connection, before, after, std::move(keys), row);
}

}  // namespace maxillo::db
