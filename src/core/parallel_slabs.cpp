#include "core/parallel_slabs.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace maxillo {
namespace {

int thread_count(int items, const SlabOptions& options) {
  int threads = options.max_threads > 0 ? options.max_threads : int(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, 8);
  return std::max(1, std::min(threads, items / std::max(1, options.min_slab_size)));
}

// Runs task(t) for t in [0, count), task 0 on this thread; the lowest-numbered exception wins.
void run_indexed(int count, const std::function<void(int)>& task) {
  std::vector<std::exception_ptr> failures(static_cast<size_t>(count));
  auto guarded = [&](int t) {
    try {
      task(t);
    } catch (...) {
      failures[size_t(t)] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(size_t(std::max(0, count - 1)));
  for (int t = 1; t < count; ++t) pool.emplace_back(guarded, t);
  if (count > 0) guarded(0);
  for (auto& thread : pool) thread.join();
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace

void for_each_slab(int first, int last, const std::function<void(int, int)>& body, const SlabOptions& options) {
  const int items = last - first;
  if (items <= 0) return;
  const int threads = thread_count(items, options);
  run_indexed(threads, [&](int t) {
    const int begin = first + int(int64_t(items) * t / threads), end = first + int(int64_t(items) * (t + 1) / threads);
    body(begin, end);
  });
}

PartRange part_range(int64_t count, int part, int parts) { return {count * part / parts, count * (part + 1) / parts}; }

void for_each_part(int parts, const std::function<void(int)>& body) {
  for_each_slab(0, parts,
                [&](int first, int last) {
                  for (int part = first; part < last; ++part) body(part);
                },
                {.min_slab_size = 1});
}

void run_concurrently(const std::vector<std::function<void()>>& tasks) {
  run_indexed(int(tasks.size()), [&](int t) { tasks[size_t(t)](); });
}

}  // namespace maxillo
