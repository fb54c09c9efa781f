// maxillo bench index [--patients 1000] [--instances 500000] [--runs 5] [--postgres URI]:
// list, show and the nightly scan on a large synthetic index (bench/index_benchmark.h).
#include <iostream>

#include "bench/index_benchmark.h"
#include "cli/command.h"
#include "core/json.h"
#include "nightly/nightly.h"

namespace maxillo::cli {
namespace {

// `nightly --summary-only`: the scan of every case, nothing to validate or summarise.
size_t nightly_scan(Archive& archive, const std::filesystem::path& out) {
  nightly::NightlyOptions options;
  options.out = out;
  options.summary_only = true;
  return nightly::run_nightly(archive, options).cases.size();
}

}  // namespace

void attach_bench_index(CLI::App& bench, CommandContext& ctx) {
  CLI::App* index = bench.add_subcommand("index", "list, show and the nightly scan on a large synthetic index");
  auto args = std::make_shared<bench::IndexBenchOptions>();
  index->add_option("--patients", args->patients, "patients (each: a study, 2 CT series, a case)")
      ->check(CLI::Range(int64_t(1), int64_t(1000000)))
      ->capture_default_str();
  index->add_option("--instances", args->instances, "instances in all")
      ->check(CLI::Range(int64_t(2), int64_t(100000000)))
      ->capture_default_str();
  index->add_option("--runs", args->runs, "runs of each query; the median is reported")->check(CLI::Range(1, 50));
  index->add_option("--postgres", args->postgres,
                    "the index on this PostgreSQL server, e.g. postgresql://postgres@127.0.0.1:5432/ (a database is "
                    "created and dropped)");
  index->add_option("--workdir", args->workdir, "scratch folder (default: $TMPDIR/maxillo-bench-index; emptied)");
  index->callback([args, &ctx] {
    const Json figures = bench::run_index_benchmark(*args, nightly_scan);
    std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::index_benchmark_text(figures, args->runs));
  });
}

}  // namespace maxillo::cli
