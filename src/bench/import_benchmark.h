#pragma once
// `maxillo bench import`: import throughput. Writes `count` 256x256 CT files (series of 200
// slices) with the series writer, imports them into a fresh archive (hashing, parsing, durable
// objects and rows included) and re-imports them; the median instances/s of each and their
// ratio. With `workers` N: N importers at once (threads, each with its own connection), each
// given every N-th series, into one archive: the aggregate rate. With `postgres`
// (postgresql://USER@HOST:PORT/): the index on that server instead of SQLite (a database per
// run, made and dropped here).
// Targets on the 2-core reference machine: >= 2000/s first import, >= 5000/s re-import.
#include <filesystem>
#include <string>

#include "core/json.h"

namespace maxillo::bench {

struct ImportBenchOptions {
  int count = 2000;               // CT files
  int runs = 3;                   // the median is reported
  int workers = 1;                // importers at once into one archive
  std::string postgres;           // server address without a database; empty: SQLite
  std::filesystem::path workdir;  // scratch folder, emptied; empty: $TMPDIR/maxillo-bench
};

// The figures: count, runs, workers, index ("sqlite" or "postgresql"), generate_seconds,
// first_import_per_s and reimport_per_s (medians of the runs), first_import_runs_per_s and
// reimport_runs_per_s (every run's), reimport_to_first_ratio.
Json run_import_benchmark(const ImportBenchOptions& options);

// The figures as `bench import` prints them, four lines.
std::string import_benchmark_text(const Json& figures);

}  // namespace maxillo::bench
