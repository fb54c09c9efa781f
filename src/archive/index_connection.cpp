#include "archive/index_connection.h"

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

}  // namespace maxillo::db
