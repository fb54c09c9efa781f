#pragma once
// Work split into disjoint slabs of an index range, run on the machine's cores.
//
// Each slab writes only its own part of the output, so the result is the same bits whatever the
// number of threads or the order in which they finish (the brief's "same input, same answer").
// An exception thrown in a slab is re-thrown to the caller after every thread has joined: the
// first slab's (lowest index) when several throw, so even the error does not depend on timing.
#include <functional>
#include <vector>

namespace maxillo {

struct SlabOptions {
  int max_threads = 0;    // <= 0: the hardware's cores (at most 8)
  int min_slab_size = 8;  // fewer items than this per thread are not worth a thread
};

// Calls body(begin, end) on disjoint [begin, end) slabs covering [first, last), in parallel.
void for_each_slab(int first, int last, const std::function<void(int, int)>& body, const SlabOptions& options = {});

// Runs the tasks at once, one thread each (the caller's thread runs the first); re-throws as above.
void run_concurrently(const std::vector<std::function<void()>>& tasks);

}  // namespace maxillo
