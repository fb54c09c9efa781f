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
#include "archive/work_queue.h"
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
  WorkQueue queue(archive, "q");
  const auto machine = [] {
    return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
  };
  const int64_t before = machine();
  const int64_t first = queue.clock_seconds();
  EXPECT_LE(std::abs(first - before), 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  const int64_t second = queue.clock_seconds();
  EXPECT_GE(second, first + 1);
  EXPECT_LE(second, first + 3);
}

TEST(WorkQueue, OffersAreIdempotentAndItemsAreClaimedInOrderOnce) {
  TemporaryFolder folder;
  Archive archive = fresh_archive(folder);
  WorkQueue queue(archive, "q");
  queue.offer({"b", "a", "c"});
  queue.offer({"a", "c"});
  EXPECT_EQ(queue.claim("w1", 1000, 60), "a");
  EXPECT_EQ(queue.claim("w2", 1000, 60), "b");
  EXPECT_EQ(queue.claim("w1", 1000, 60), "c");
  EXPECT_EQ(queue.claim("w2", 1000, 60), std::nullopt);
  auto counts = queue.counts(1000);
  EXPECT_EQ(counts.pending, 0u);
  EXPECT_EQ(counts.leased, 3u);
  EXPECT_EQ(WorkQueue(archive, "other queue").claim("w1", 1000, 60), std::nullopt);
}

TEST(WorkQueue, AnEndedLeaseIsTakenOverAndTheOldHolderCanNoLongerFinish) {
  TemporaryFolder folder;
  Archive archive = fresh_archive(folder);
  WorkQueue queue(archive, "q");
  queue.offer({"case:1:abc"});
  ASSERT_EQ(queue.claim("dead", 1000, 10), "case:1:abc");
  EXPECT_EQ(queue.claim("alive", 1009, 10), std::nullopt);  // still leased
  EXPECT_EQ(queue.counts(1009).leased, 1u);
  EXPECT_EQ(queue.counts(1010).pending, 1u);  // the lease ended
  ASSERT_EQ(queue.claim("alive", 1010, 10), "case:1:abc");
  EXPECT_FALSE(queue.renew("case:1:abc", "dead", 2000));
  EXPECT_FALSE(queue.finish("case:1:abc", "dead", "done"));
  EXPECT_TRUE(queue.renew("case:1:abc", "alive", 1100));
  EXPECT_EQ(queue.claim("third", 1050, 10), std::nullopt);  // renewed past 1050
  EXPECT_TRUE(queue.finish("case:1:abc", "alive", "done"));
  auto records = queue.records();
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].state, "done");
  EXPECT_EQ(records[0].holder, "alive");
  EXPECT_EQ(records[0].claims, 2);
}

TEST(WorkQueue, FinishedItemsAreNeverClaimedAgainEvenWhenOfferedAgain) {
  TemporaryFolder folder;
  Archive archive = fresh_archive(folder);
  WorkQueue queue(archive, "q");
  queue.offer({"x", "y"});
  ASSERT_EQ(queue.claim("w", 1, 5), "x");
  ASSERT_TRUE(queue.finish("x", "w", "failed", "bad input"));
  ASSERT_EQ(queue.claim("w", 1, 5), "y");
  ASSERT_TRUE(queue.finish("y", "w", "done"));
  EXPECT_FALSE(queue.finish("y", "w", "done"));  // finished once
  queue.offer({"x", "y"});
  EXPECT_EQ(queue.claim("w", 100000, 5), std::nullopt);
  auto counts = queue.counts(100000);
  EXPECT_EQ(counts.finished, 2u);
  EXPECT_EQ(counts.pending + counts.leased, 0u);
  EXPECT_EQ(queue.records()[0].reason, "bad input");
}

TEST(WorkQueue, ConcurrentWorkersClaimEveryItemExactlyOnce) {
  TemporaryFolder folder;
  const auto address = testing::archive_at(folder / "archive");
  std::vector<std::string> items;
  for (int n = 0; n < 60; ++n) items.push_back("item-" + std::to_string(1000 + n));
  {
    Archive archive = Archive::open(address, OpenMode::CreateIfMissing);
    WorkQueue(archive, "q").offer(items);
  }
  std::mutex mutex;
  std::vector<std::string> claimed;
  std::vector<std::thread> workers;
  for (int w = 0; w < 4; ++w)
    workers.emplace_back([&, w] {
      Archive archive = Archive::open(address);
      WorkQueue queue(archive, "q");
      const std::string name = "worker-" + std::to_string(w);
      while (auto item = queue.claim(name, 1000, 3600)) {
        EXPECT_TRUE(queue.finish(*item, name, "done"));
        std::lock_guard lock(mutex);
        claimed.push_back(*item);
      }
    });
  for (auto& worker : workers) worker.join();
  std::sort(claimed.begin(), claimed.end());
  EXPECT_EQ(claimed, items);  // every item, none twice
  Archive archive = Archive::open(address);
  for (const auto& record : WorkQueue(archive, "q").records()) EXPECT_EQ(record.claims, 1) << record.item;
}

}  // namespace
}  // namespace maxillo
