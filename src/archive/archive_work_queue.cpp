// Work shared between processes and nodes: offered once, claimed under a lease, finished once.
#include "archive/archive_sql.h"
#include "archive/archive_state.h"

namespace maxillo {

void Archive::offer_work(std::string_view queue, const std::vector<std::string>& items) {
  db::retry_transaction([&] {
    db::Transaction transaction(state_->db, db::TransactionKind::Deferred);
    db::Statement offer(state_->db, sql::kOfferWork);
    for (const auto& item : items) offer.reset().bind(1, queue).bind(2, item).run();
    transaction.commit();
  });
}

int64_t Archive::clock_seconds() const { return state_->db.clock_seconds(); }

std::optional<std::string> Archive::claim_work(std::string_view queue, std::string_view holder, int64_t now,
                                               int64_t lease_seconds) {
  // An index that locks single rows (PostgreSQL) locks the row it picks and lets other claims
  // skip it; else the index's write lock is taken before looking (SQLite's BEGIN IMMEDIATE), so
  // two claims never see the same free item.
  const bool embedded = !state_->db.locks_rows();
  std::optional<std::string> claimed;
  db::retry_transaction([&] {
    claimed.reset();
    db::Transaction transaction(state_->db, embedded ? db::TransactionKind::Immediate : db::TransactionKind::Deferred);
    db::Statement candidate(state_->db, embedded ? sql::kClaimableWork : sql::kClaimableWorkSkipLocked);
    candidate.bind(1, queue).bind(2, now);
    if (candidate.step()) claimed = candidate.text(0);
    candidate.reset();
    if (claimed) {
      db::Statement lease(state_->db, sql::kLeaseWork);
      lease.bind(1, queue).bind(2, *claimed).bind(3, holder).bind(4, now + lease_seconds).run();
    }
    transaction.commit();
  });
  return claimed;
}

bool Archive::renew_work(std::string_view queue, std::string_view item, std::string_view holder, int64_t until) {
  db::Statement renew(state_->db, sql::kRenewWork);
  return renew.bind(1, queue).bind(2, item).bind(3, holder).bind(4, until).run() == 1;
}

bool Archive::finish_work(std::string_view queue, std::string_view item, std::string_view holder,
                          std::string_view state, std::string_view reason) {
  db::Statement finish(state_->db, sql::kFinishWork);
  return finish.bind(1, queue).bind(2, item).bind(3, holder).bind(4, state).bind(5, reason).run() == 1;
}

Archive::WorkCounts Archive::work_counts(std::string_view queue, int64_t now) const {
  db::Statement count(state_->db, sql::kCountWork);
  count.bind(1, queue).bind(2, now);
  WorkCounts counts;
  if (count.step()) {
    counts.pending = size_t(count.integer(0));
    counts.leased = size_t(count.integer(1));
    counts.finished = size_t(count.integer(2));
  }
  return counts;
}

std::vector<Archive::WorkRecord> Archive::work_records(std::string_view queue) const {
  db::Statement rows(state_->db, sql::kWorkRecords);
  rows.bind(1, queue);
  std::vector<WorkRecord> records;
  while (rows.step())
    records.push_back({rows.text(0), rows.text(1), rows.text(2), rows.text(3), rows.integer(4), rows.integer(5)});
  return records;
}

}  // namespace maxillo
