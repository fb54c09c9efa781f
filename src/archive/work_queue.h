#pragma once
// Work shared between processes and nodes (db/003_work_queue.sql): items offered once, claimed
// by one worker at a time under a lease, taken over when a lease ends, finished once. `maxillo
// nightly --claim` shares the nightly validation through it (nightly/nightly_worker.h) and
// `bench claim` times it. The same semantics on an embedded index and on a PostgreSQL server.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "archive/archive.h"

namespace maxillo {

namespace db {
class Connection;
}

struct WorkCounts {
  size_t pending = 0;   // nobody holds them (never leased, or the lease ended)
  size_t leased = 0;    // held by a live lease at `now`
  size_t finished = 0;  // done, failed or superseded
};

// An item's state ("pending", "done", "failed", "superseded"), its last holder and what it said.
struct WorkRecord {
  std::string item, state, holder, reason;
  int64_t claims = 0;
  int64_t expires_at = 0;  // the lease's end (Unix seconds, the index's clock); 0: never leased
};

// The queue `name` of an archive's index, on the archive's connection: the archive outlives it.
class WorkQueue {
 public:
  WorkQueue(Archive& archive, std::string name);

  // Adds the items the queue does not hold yet (idempotent; finished items stay finished).
  void offer(const std::vector<std::string>& items);
  // The index's clock (Unix seconds) for `now` and lease ends: the database server's on
  // PostgreSQL, so nodes whose clocks disagree still agree on when a lease ends.
  int64_t clock_seconds() const;
  // Leases the first pending item (by name) that nobody holds, or whose lease ended before
  // `now` (Unix seconds), to `holder` until now + lease_seconds. Nothing when no item can be
  // claimed now. On PostgreSQL, SELECT ... FOR UPDATE SKIP LOCKED: workers never wait for
  // each other's claims; on SQLite, BEGIN IMMEDIATE.
  std::optional<std::string> claim(std::string_view holder, int64_t now, int64_t lease_seconds);
  // Extends a lease the holder still holds; false when it has lost it.
  bool renew(std::string_view item, std::string_view holder, int64_t until);
  // Ends the holder's lease with the item's state ("done", "failed", "superseded"); false when
  // the holder no longer held it (another worker took over an expired lease).
  bool finish(std::string_view item, std::string_view holder, std::string_view state, std::string_view reason = {});
  WorkCounts counts(int64_t now) const;
  // Every item's state and holder, by item, for reports and tests.
  std::vector<WorkRecord> records() const;

 private:
  db::Connection& index_;
  std::string name_;
};

}  // namespace maxillo
