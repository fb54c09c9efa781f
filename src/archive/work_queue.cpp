#include "archive/work_queue.h"

#include "archive/archive_sql.h"
#include "archive/archive_state.h"

namespace maxillo {

WorkQueue::WorkQueue(Archive& archive, std::string name) : index_(archive.state_->db), name_(std::move(name)) {}

void WorkQueue::offer(const std::vector<std::string>& items) {
  db::retry_transaction([&] {
    db::Transaction transaction(index_, db::TransactionKind::Deferred);
    db::Statement offer(index_, sql::kOfferWork);
    for (const auto& item : items) offer.reset().bind(1, name_).bind(2, item).run();
    transaction.commit();
  });
}

int64_t WorkQueue::clock_seconds() const { return index_.clock_seconds(); }

std::optional<std::string> WorkQueue::claim(std::string_view holder, int64_t now, int64_t lease_seconds) {
  // An index that locks single rows (PostgreSQL) locks the row it picks and lets other claims
  // skip it; else the index's write lock is taken before looking (SQLite's BEGIN IMMEDIATE), so
  // two claims never see the same free item.
  const bool embedded = !index_.locks_rows();
  std::optional<std::string> claimed;
  db::retry_transaction([&] {
    claimed.reset();
    db::Transaction transaction(index_, embedded ? db::TransactionKind::Immediate : db::TransactionKind::Deferred);
    db::Statement candidate(index_, embedded ? sql::kClaimableWork : sql::kClaimableWorkSkipLocked);
    candidate.bind(1, name_).bind(2, now);
    if (candidate.step()) claimed = candidate.text(0);
    candidate.reset();
    if (claimed) {
      db::Statement lease(index_, sql::kLeaseWork);
      lease.bind(1, name_).bind(2, *claimed).bind(3, holder).bind(4, now + lease_seconds).run();
    }
    transaction.commit();
  });
  return claimed;
}

bool WorkQueue::renew(std::string_view item, std::string_view holder, int64_t until) {
  db::Statement renew(index_, sql::kRenewWork);
  return renew.bind(1, name_).bind(2, item).bind(3, holder).bind(4, until).run() == 1;
}

bool WorkQueue::finish(std::string_view item, std::string_view holder, std::string_view state,
                       std::string_view reason) {
  db::Statement finish(index_, sql::kFinishWork);
  return finish.bind(1, name_).bind(2, item).bind(3, holder).bind(4, state).bind(5, reason).run() == 1;
}

WorkCounts WorkQueue::counts(int64_t now) const {
  db::Statement count(index_, sql::kCountWork);
  count.bind(1, name_).bind(2, now);
  WorkCounts counts;
  if (count.step()) {
    counts.pending = size_t(count.integer(0));
    counts.leased = size_t(count.integer(1));
    counts.finished = size_t(count.integer(2));
  }
  return counts;
}

std::vector<WorkRecord> WorkQueue::records() const {
  db::Statement rows(index_, sql::kWorkRecords);
  rows.bind(1, name_);
  std::vector<WorkRecord> records;
  while (rows.step())
    records.push_back({rows.text(0), rows.text(1), rows.text(2), rows.text(3), rows.integer(4), rows.integer(5)});
  return records;
}

}  // namespace maxillo
