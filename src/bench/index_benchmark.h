#pragma once
// `maxillo bench index`: queries on an index of a hospital's size. Fills a scratch archive with
// synthetic rows in bulk (archive/synthetic_index.h: per patient a study, a pre- and a
// post-operative CT series, the default case), gives every case a plan and landmarks (so every
// case is eligible for the nightly validation), then times what users wait for: `list
// patients`, `list series`, `show` of one case, resolving a Patient ID, and the nightly scan
// (`nightly --summary-only` with nothing validated yet: every case's validation inputs hash and
// stored validation looked up, all `nightly` does before deciding what to validate). Medians of
// `runs`.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "archive/archive.h"
#include "core/json.h"

namespace maxillo::bench {

struct IndexBenchOptions {
  int64_t patients = 1000;        // each: a study, 2 CT series, a case
  int64_t instances = 500000;     // in all
  int runs = 5;                   // of each query; the median is reported
  std::string postgres;           // server address without a database; empty: SQLite
  std::filesystem::path workdir;  // scratch folder, emptied; empty: $TMPDIR/maxillo-bench-index
};

// The nightly scan: `nightly --summary-only` on `archive`, its output in the folder `out`;
// returns how many eligible cases it found. The nightly job lives above the benchmarks (it links
// the report sections), so the command passes its scan in.
using NightlyScan = std::function<size_t(Archive& archive, const std::filesystem::path& out)>;

// The figures: index ("SQLite" or "PostgreSQL"), patients, instances, fill_seconds,
// plans_and_landmarks_seconds, eligible_cases (the nightly scan's) and median_seconds of each
// query by its name ("list patients", "list series", "show case", "resolve Patient ID",
// "nightly scan").
Json run_index_benchmark(const IndexBenchOptions& options, const NightlyScan& nightly_scan);

// The figures as `bench index` prints them: a line of the index, a line per query (the median
// of `runs`), the eligible cases.
std::string index_benchmark_text(const Json& figures, int runs);

}  // namespace maxillo::bench
