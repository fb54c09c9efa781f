#include "core/parallel_slabs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace maxillo {
namespace {

TEST(ParallelSlabs, EveryIndexIsVisitedExactlyOnceWhateverTheThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<std::atomic<int>> visits(1001);
    for_each_slab(0, 1001,
                  [&](int begin, int end) {
                    for (int i = begin; i < end; ++i) ++visits[size_t(i)];
                  },
                  {.max_threads = threads, .min_slab_size = 1});
    for (size_t i = 0; i < visits.size(); ++i)
      ASSERT_EQ(visits[i].load(), 1) << "index " << i << ", " << threads << " threads";
  }
}

TEST(ParallelSlabs, SlabsAreContiguousAndCoverTheRangeInOrder) {
  std::vector<std::pair<int, int>> slabs(8, {-1, -1});
  std::atomic<int> next{0};
  for_each_slab(5, 45,
                [&](int begin, int end) {
                  slabs[size_t(next++)] = {begin, end};
                },
                {.max_threads = 4, .min_slab_size = 1});
  ASSERT_EQ(next.load(), 4);
  slabs.resize(4);
  std::sort(slabs.begin(), slabs.end());
  EXPECT_EQ(slabs.front().first, 5);
  EXPECT_EQ(slabs.back().second, 45);
  for (size_t s = 1; s < slabs.size(); ++s) EXPECT_EQ(slabs[s].first, slabs[s - 1].second);
}

TEST(ParallelSlabs, PartsCoverTheRangeInOrderWhateverTheirCount) {
  for (int64_t count : {0, 3, 8, 2499}) {
    int64_t next = 0;
    for (int part = 0; part < 8; ++part) {
      const PartRange range = part_range(count, part, 8);
      EXPECT_EQ(range.begin, next) << count << " items, part " << part;
      EXPECT_GE(range.end, range.begin);
      EXPECT_LE(range.end - range.begin, count / 8 + 1);  // as even as integers allow
      next = range.end;
    }
    EXPECT_EQ(next, count);
  }
}

TEST(ParallelSlabs, EveryPartRunsExactlyOnce) {
  std::vector<std::atomic<int>> runs(16);
  for_each_part(16, [&](int part) { ++runs[size_t(part)]; });
  for (size_t part = 0; part < runs.size(); ++part) EXPECT_EQ(runs[part].load(), 1) << "part " << part;
}

TEST(ParallelSlabs, AnEmptyRangeRunsNothing) {
  bool ran = false;
  for_each_slab(3, 3, [&](int, int) { ran = true; });
  for_each_slab(4, 2, [&](int, int) { ran = true; });
  EXPECT_FALSE(ran);
}

TEST(ParallelSlabs, TheLowestSlabsErrorReachesTheCallerAfterAllThreadsEnded) {
  std::atomic<int> finished{0};
  try {
    for_each_slab(0, 4,
                  [&](int begin, int) {
                    ++finished;
                    throw std::runtime_error("slab " + std::to_string(begin));
                  },
                  {.max_threads = 4, .min_slab_size = 1});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "slab 0");
  }
  EXPECT_EQ(finished.load(), 4);
}

TEST(ParallelSlabs, RunConcurrentlyRunsEveryTaskAndReportsTheFirstFailure) {
  std::atomic<int> ran{0};
  EXPECT_THROW(run_concurrently({[&] { ++ran; },
                                 [&] {
                                   ++ran;
                                   throw std::logic_error("second");
                                 },
                                 [&] { ++ran; }}),
               std::logic_error);
  EXPECT_EQ(ran.load(), 3);
  run_concurrently({});
}

}  // namespace
}  // namespace maxillo
