#pragma once
// Work split into disjoint slabs of an index range, run on the machine's cores.
//
// Each slab writes only its own part of the output, so the result is the same bits whatever the
// number of threads or the order in which they finish (the brief's "same input, same answer").
// An exception thrown in a slab is re-thrown to the caller after every thread has joined: the
// first slab's (lowest index) when several throw, so even the error does not depend on timing.
#include <cstdint>
#include <functional>
#include <vector>

namespace maxillo {

struct SlabOptions {
  int max_threads = 0;    // <= 0: the hardware's cores (at most 8)
  int min_slab_size = 8;  // fewer items than this per thread are not worth a thread
};

// Calls body(begin, end) on disjoint [begin, end) slabs covering [first, last), in parallel.
void for_each_slab(int first, int last, const std::function<void(int, int)>& body, const SlabOptions& options = {});

// A fixed split of [0, count) into `parts` contiguous ranges, in order; it depends on nothing but
// its arguments. For sums whose partial results are kept per part and joined in part order, so
// that the answer is the same bits whatever the number of threads.
struct PartRange {
  int64_t begin = 0, end = 0;
};
PartRange part_range(int64_t count, int part, int parts);

// Calls body(part) for every part of [0, parts), in parallel on the machine's cores.
void for_each_part(int parts, const std::function<void(int)>& body);

// Runs the tasks at once, one thread each (the caller's thread runs the first); re-throws as above.
void run_concurrently(const std::vector<std::function<void()>>& tasks);

}  // namespace maxillo
