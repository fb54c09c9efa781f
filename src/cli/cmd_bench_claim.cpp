// maxillo bench claim [--items 2000] [--workers 4] [--runs 3] [--postgres URI]: the work
// queue's rate (nightly --claim). Offers `items` items, then `workers` threads (each with its
// own connection, as processes on other nodes would have) claim and finish them until none is
// left; prints the median claims/s (a claim and its finish) and checks that every item was
// claimed exactly once.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <thread>

#include "archive/archive.h"
#include "cli/bench_archive.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

struct ClaimArguments {
  int items = 2000;
  int workers = 4;
  int runs = 3;
  std::string postgres;
  std::filesystem::path workdir;
};

// Every worker claims and finishes until the queue is empty; returns claims per second.
double timed_claims(const std::filesystem::path& address, int items, int workers) {
  const char* queue = "bench";
  std::vector<std::string> names;
  for (int n = 0; n < items; ++n) names.push_back("item-" + std::to_string(1000000 + n));
  std::vector<Archive> archives;
  for (int w = 0; w < workers; ++w) archives.push_back(Archive::open(address));
  archives.front().offer_work(queue, names);
  std::mutex mutex;
  size_t claimed = 0;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      const std::string holder = "bench-worker-" + std::to_string(w);
      size_t mine = 0;
      while (auto item = archives[size_t(w)].claim_work(queue, holder, 1000, 3600)) {
        archives[size_t(w)].finish_work(queue, *item, holder, "done");
        ++mine;
      }
      std::lock_guard lock(mutex);
      claimed += mine;
    });
  for (auto& thread : threads) thread.join();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& record : archives.front().work_records(queue))
    if (record.claims != 1 || record.state != "done")
      throw Error(ErrorCode::kProcessing, record.item, "claimed " + std::to_string(record.claims) + " times");
  if (claimed != size_t(items)) throw Error(ErrorCode::kProcessing, "bench claim", "not every item was claimed once");
  return double(items) / seconds;
}

void run_bench_claim(const ClaimArguments& args, CommandContext& ctx) {
  const auto workdir =
      args.workdir.empty() ? std::filesystem::temp_directory_path() / "maxillo-bench-claim" : args.workdir;
  std::vector<double> rates;
  const char* engine = args.postgres.empty() ? "SQLite" : "PostgreSQL";
  for (int run = 0; run < args.runs; ++run) {
    BenchArchive archive(args.postgres, workdir / ("archive" + std::to_string(run)), run);
    { Archive::open(archive.address(), OpenMode::CreateIfMissing); }
    rates.push_back(timed_claims(archive.address(), args.items, args.workers));
  }
  if (ctx.global.json) {
    std::cout << Json{{"items", args.items}, {"workers", args.workers},       {"runs", args.runs},
                      {"index", engine},     {"claims_per_s", median(rates)}, {"runs_claims_per_s", rates}}
                     .dump(2)
              << "\n";
  } else {
    std::printf("%d items, %d workers at once, index on %s: %.0f claims/s (claim + finish; median of %d)\n", args.items,
                args.workers, engine, median(rates), args.runs);
  }
}

}  // namespace

void attach_bench_claim(CLI::App& bench, CommandContext& ctx) {
  CLI::App* claim = bench.add_subcommand("claim", "work queue rate (nightly --claim): claims/s with N workers at once");
  auto args = std::make_shared<ClaimArguments>();
  claim->add_option("--items", args->items, "items offered")->check(CLI::Range(1, 1000000))->capture_default_str();
  claim->add_option("--workers", args->workers, "workers at once (threads, own connections)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  claim->add_option("--runs", args->runs, "runs; the median is reported")
      ->check(CLI::Range(1, 50))
      ->capture_default_str();
  claim->add_option(
      "--postgres", args->postgres,
      "the index on this PostgreSQL server, e.g. postgresql://postgres@127.0.0.1:5432/ (a database per run "
      "is created and dropped)");
  claim->add_option("--workdir", args->workdir, "scratch folder (default: $TMPDIR/maxillo-bench-claim; emptied)");
  claim->callback([args, &ctx] { run_bench_claim(*args, ctx); });
}

}  // namespace maxillo::cli
