#pragma once
// `maxillo bench import`: import throughput. Writes `count` 256x256 CT files (series of 200
// slices) with the series writer, imports them into a fresh archive (hashing, parsing, durable
// objects and rows included) and re-imports them; the median instances/s of each and their
// ratio. With `workers` N: N importers at once (threads, each with its own connection) into one
// archive, each given every N-th series (disjoint inputs) or every series (overlapping inputs:
// each instance arrives N times and is archived once; the rate counts it once). With `postgres`
// (postgresql://USER@HOST:PORT/): the index on that server instead of SQLite (a database per
// run, made and dropped here). CPU seconds of this process (the clients) and, for a server on
// this machine, of the server's processes, for the median first import.
// Targets on the 2-core reference machine: >= 2000/s first import, >= 5000/s re-import.
#include <filesystem>
#include <string>
#include <vector>

#include "core/json.h"

namespace maxillo::bench {

struct ImportBenchOptions {
  int count = 2000;               // CT files
  int runs = 3;                   // the median is reported
  int workers = 1;                // importers at once into one archive
  bool overlapping = false;       // every importer given every file, not a share of them
  std::string postgres;           // server address without a database; empty: SQLite
  std::filesystem::path workdir;  // scratch folder, emptied; empty: $TMPDIR/maxillo-bench
};

// The figures: count, runs, workers, inputs ("disjoint" or "overlapping"), index ("sqlite" or
// "postgresql"), generate_seconds, first_import_per_s and reimport_per_s (medians of the runs),
// first_import_runs_per_s and reimport_runs_per_s (every run's), reimport_to_first_ratio,
// client_cpu_seconds and server_cpu_seconds (of the median first import; the server's null
// when not measurable: SQLite, a server elsewhere).
Json run_import_benchmark(const ImportBenchOptions& options);
// One run of the above per number of workers and per kind of input (false: disjoint, true:
// overlapping), on files generated once; options.workers and options.overlapping are ignored.
std::vector<Json> run_import_benchmarks(const ImportBenchOptions& options, const std::vector<int>& workers,
                                        const std::vector<bool>& overlapping);

// The figures as `bench import` prints them, four lines.
std::string import_benchmark_text(const Json& figures);
// Several runs' figures as one table, a line per run.
std::string import_benchmark_table(const std::vector<Json>& runs);

}  // namespace maxillo::bench
