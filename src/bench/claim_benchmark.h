#pragma once
// `maxillo bench claim`: the work queue's rate (nightly --claim). Offers `items` items, then
// `workers` threads (each with its own connection, as processes on other nodes would have)
// claim and finish them until none is left; the median claims/s (a claim and its finish), after
// checking that every item was claimed exactly once. With `postgres`
// (postgresql://USER@HOST:PORT/): the queue on that server instead of SQLite (a database per
// run, made and dropped here).
#include <filesystem>
#include <string>

#include "core/json.h"

namespace maxillo::bench {

struct ClaimBenchOptions {
  int items = 2000;               // items offered
  int workers = 4;                // workers at once
  int runs = 3;                   // the median is reported
  std::string postgres;           // server address without a database; empty: SQLite
  std::filesystem::path workdir;  // scratch folder, emptied; empty: $TMPDIR/maxillo-bench-claim
};

// The figures: items, workers, runs, index ("SQLite" or "PostgreSQL"), claims_per_s (the
// median) and runs_claims_per_s (every run's). Error(kProcessing) when an item was not claimed
// exactly once.
Json run_claim_benchmark(const ClaimBenchOptions& options);

// The figures as `bench claim` prints them, one line.
std::string claim_benchmark_text(const Json& figures);

}  // namespace maxillo::bench
