// maxillo bench claim [--items 2000] [--workers 4] [--runs 3] [--postgres URI]: the work
// queue's rate (nightly --claim), claims/s with N workers at once (bench/claim_benchmark.h).
#include <iostream>

#include "bench/claim_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {

void attach_bench_claim(CLI::App& bench, CommandContext& ctx) {
  CLI::App* claim = bench.add_subcommand("claim", "work queue rate (nightly --claim): claims/s with N workers at once");
  auto args = std::make_shared<bench::ClaimBenchOptions>();
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
  claim->callback([args, &ctx] {
    const Json figures = bench::run_claim_benchmark(*args);
    std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::claim_benchmark_text(figures));
  });
}

}  // namespace maxillo::cli
