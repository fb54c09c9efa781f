// The work queue (db/003_work_queue.sql) that `nightly --claim` workers share: each item is
// claimed by one worker at a time, taken over when a lease ends, and finished once. Runs on
// SQLite and, through the PostgreSQL fixture, on a server index.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <set>
#include <thread>

#include "archive/archive.h"
#include "archive_fixture.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

Archive fresh_archive(const TemporaryFolder& folder) {
  return Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
}

// Leases are timed by the index's clock (the server's, on PostgreSQL): Unix seconds, moving on,
// and here (server and test on one machine) this machine's time to within a second or two.
TEST(WorkQueue, TheIndexClockIsUnixSecondsAndMovesOn) {
  TemporaryFolder folder;
  Archive archive = fresh_archive(folder);
  const auto machine = [] {
    return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
  };
  const int64_t before = machine();
  const int64_t first = archive.clock_seconds();
  EXPECT_LE(std::abs(first - before), 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  const int64_t second = archive.clock_seconds();
  EXPECT_GE(second, first + 1);
  EXPECT_LE(second, first + 3);
}

TEST(WorkQueue, OffersAreIdempotentAndItemsAreClaimedInOrderOnce) {
  TemporaryFolder folder;
  Archive archive = fresh_archive(folder);
  archive.offer_work("q", {"b", "a", "c"});
  archive.offer_work("q", {"a", "c"});
  EXPECT_EQ(archive.claim_work("q", "w1", 1000, 60), "a");
  EXPECT_EQ(archive.claim_work("q", "w2", 1000, 60), "b");
  EXPECT_EQ(archive.claim_work("q", "w1", 1000, 60), "c");
  EXPECT_EQ(archive.claim_work("q", "w2", 1000, 60), std::nullopt);
  auto counts = archive.work_counts("q", 1000);
  EXPECT_EQ(counts.pending, 0u);
  EXPECT_EQ(counts.leased, 3u);
  EXPECT_EQ(archive.claim_work("other queue", "w1", 1000, 60), std::nullopt);
}

TEST(WorkQueue, AnEndedLeaseIsTakenOverAndTheOldHolderCanNoLongerFinish) {
  TemporaryFolder folder;
  Archive archive = fresh_archive(folder);
  archive.offer_work("q", {"case:1:abc"});
  ASSERT_EQ(archive.claim_work("q", "dead", 1000, 10), "case:1:abc");
  EXPECT_EQ(archive.claim_work("q", "alive", 1009, 10), std::nullopt);  // still leased
  EXPECT_EQ(archive.work_counts("q", 1009).leased, 1u);
  EXPECT_EQ(archive.work_counts("q", 1010).pending, 1u);  // the lease ended
  ASSERT_EQ(archive.claim_work("q", "alive", 1010, 10), "case:1:abc");
  EXPECT_FALSE(archive.renew_work("q", "case:1:abc", "dead", 2000));
  EXPECT_FALSE(archive.finish_work("q", "case:1:abc", "dead", "done"));
  EXPECT_TRUE(archive.renew_work("q", "case:1:abc", "alive", 1100));
  EXPECT_EQ(archive.claim_work("q", "third", 1050, 10), std::nullopt);  // renewed past 1050
  EXPECT_TRUE(archive.finish_work("q", "case:1:abc", "alive", "done"));
  auto records = archive.work_records("q");
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].state, "done");
  EXPECT_EQ(records[0].holder, "alive");
  EXPECT_EQ(records[0].claims, 2);
}

TEST(WorkQueue, FinishedItemsAreNeverClaimedAgainEvenWhenOfferedAgain) {
  TemporaryFolder folder;
  Archive archive = fresh_archive(folder);
  archive.offer_work("q", {"x", "y"});
  ASSERT_EQ(archive.claim_work("q", "w", 1, 5), "x");
  ASSERT_TRUE(archive.finish_work("q", "x", "w", "failed", "bad input"));
  ASSERT_EQ(archive.claim_work("q", "w", 1, 5), "y");
  ASSERT_TRUE(archive.finish_work("q", "y", "w", "done"));
  EXPECT_FALSE(archive.finish_work("q", "y", "w", "done"));  // finished once
  archive.offer_work("q", {"x", "y"});
  EXPECT_EQ(archive.claim_work("q", "w", 100000, 5), std::nullopt);
  auto counts = archive.work_counts("q", 100000);
  EXPECT_EQ(counts.finished, 2u);
  EXPECT_EQ(counts.pending + counts.leased, 0u);
  EXPECT_EQ(archive.work_records("q")[0].reason, "bad input");
}

TEST(WorkQueue, ConcurrentWorkersClaimEveryItemExactlyOnce) {
  TemporaryFolder folder;
  const auto address = testing::archive_at(folder / "archive");
  std::vector<std::string> items;
  for (int n = 0; n < 60; ++n) items.push_back("item-" + std::to_string(1000 + n));
  { Archive::open(address, OpenMode::CreateIfMissing).offer_work("q", items); }
  std::mutex mutex;
  std::vector<std::string> claimed;
  std::vector<std::thread> workers;
  for (int w = 0; w < 4; ++w)
    workers.emplace_back([&, w] {
      Archive archive = Archive::open(address);
      const std::string name = "worker-" + std::to_string(w);
      while (auto item = archive.claim_work("q", name, 1000, 3600)) {
        EXPECT_TRUE(archive.finish_work("q", *item, name, "done"));
        std::lock_guard lock(mutex);
        claimed.push_back(*item);
      }
    });
  for (auto& worker : workers) worker.join();
  std::sort(claimed.begin(), claimed.end());
  EXPECT_EQ(claimed, items);  // every item, none twice
  Archive archive = Archive::open(address);
  for (const auto& record : archive.work_records("q")) EXPECT_EQ(record.claims, 1) << record.item;
}

}  // namespace
}  // namespace maxillo
