#include "bench/import_benchmark.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

#include "archive/archive.h"
#include "bench/formatted.h"
#include "bench/scratch_archive.h"
#include "bench/timing.h"
#include "core/error.h"
#include "dicom/dicom_series_writer.h"

namespace maxillo::bench {
namespace {

// `count` slices of one synthetic 256x256 CT, written as series of 200 slices of five patients;
// returns the series folders.
std::vector<std::filesystem::path> generate_files(const std::filesystem::path& folder, int count) {
  constexpr int kSlicesPerSeries = 200;
  Volume volume;
  volume.geometry.size = {256, 256, std::min(count, kSlicesPerSeries)};
  volume.geometry.spacing = {0.5, 0.5, 0.5};
  volume.hu.resize(size_t(volume.geometry.voxel_count()));
  for (size_t n = 0; n < volume.hu.size(); ++n) volume.hu[n] = int16_t(int(n * 7919 % 4000) - 1000);
  std::vector<std::filesystem::path> folders;
  for (int done = 0, series = 0; done < count; ++series) {
    int slices = std::min(kSlicesPerSeries, count - done);
    volume.geometry.size.z() = slices;
    volume.hu.resize(size_t(volume.geometry.voxel_count()));
    SeriesMetadata metadata;
    metadata.patient_id = "BENCH" + std::to_string(series % 5);
    metadata.patient_name = "Bench^Patient";
    metadata.study_date = "20240101";
    metadata.series_number = series + 1;
    auto series_folder = folder / ("series" + std::to_string(series));
    write_ct_series(volume, metadata, series_folder);
    folders.push_back(series_folder);
    done += slices;
  }
  return folders;
}

// The workers' reports added up.
ImportReport added_up(const std::vector<ImportReport>& reports) {
  ImportReport total;
  for (const auto& r : reports) {
    total.imported += r.imported;
    total.already_archived += r.already_archived;
    total.conflicts += r.conflicts;
    total.failed += r.failed;
  }
  return total;
}

// Every worker imports its share (every N-th series folder) into the archive at `address`, all
// at once; returns the aggregate instances/s.
double timed_import(const std::filesystem::path& address, const std::vector<std::filesystem::path>& inputs, int workers,
                    size_t expected_imported, size_t expected_known) {
  ImportOptions options;
  options.progress = ProgressDisplay::Never;
  std::vector<ImportReport> reports(static_cast<size_t>(workers));
  std::vector<std::exception_ptr> failures(static_cast<size_t>(workers));
  std::vector<Archive> archives;
  for (int w = 0; w < workers; ++w) archives.push_back(Archive::open(address));
  const auto start = Clock::now();
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      std::vector<std::filesystem::path> share;
      for (size_t n = size_t(w); n < inputs.size(); n += size_t(workers)) share.push_back(inputs[n]);
      try {
        reports[size_t(w)] = archives[size_t(w)].import_paths(share, options);
      } catch (...) {
        failures[size_t(w)] = std::current_exception();
      }
    });
  for (auto& thread : threads) thread.join();
  const double seconds = seconds_since(start);
  for (auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  // An import that did not give the expected counts is no measurement of import.
  const ImportReport total = added_up(reports);
  if (total.imported != expected_imported || total.already_archived != expected_known || !total.all_ok())
    throw Error(ErrorCode::kProcessing, address.string(), "benchmark import did not give the expected counts");
  return double(total.files()) / seconds;
}

}  // namespace

Json run_import_benchmark(const ImportBenchOptions& options) {
  const auto workdir =
      options.workdir.empty() ? std::filesystem::temp_directory_path() / "maxillo-bench" : options.workdir;
  std::filesystem::remove_all(workdir);
  // Removed however the run ends (a refused login, a failed import), not only when it succeeds.
  struct RemovedOnExit {
    std::filesystem::path folder;
    ~RemovedOnExit() {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  } removed_on_exit{workdir};
  std::vector<std::filesystem::path> inputs;
  const double generate_seconds = seconds_of([&] { inputs = generate_files(workdir / "input", options.count); });

  std::vector<double> first, again;
  for (int run = 0; run < options.runs; ++run) {
    ScratchArchive archive(options.postgres, workdir / ("archive" + std::to_string(run)), run);
    { Archive::open(archive.address(), OpenMode::CreateIfMissing); }
    first.push_back(timed_import(archive.address(), inputs, options.workers, size_t(options.count), 0));
    again.push_back(timed_import(archive.address(), inputs, options.workers, 0, size_t(options.count)));
  }
  const double first_rate = median(first), again_rate = median(again);
  return {{"count", options.count},
          {"runs", options.runs},
          {"workers", options.workers},
          {"index", options.postgres.empty() ? "sqlite" : "postgresql"},
          {"generate_seconds", generate_seconds},
          {"first_import_per_s", first_rate},
          {"reimport_per_s", again_rate},
          {"first_import_runs_per_s", first},
          {"reimport_runs_per_s", again},
          {"reimport_to_first_ratio", again_rate / first_rate}};
}

std::string import_benchmark_text(const Json& figures) {
  const int runs = figures["runs"].get<int>();
  return formatted("generated %d files of 256x256 in %.2f s; %d importer(s) at once, index on %s\n",
                   figures["count"].get<int>(), figures["generate_seconds"].get<double>(),
                   figures["workers"].get<int>(), figures["index"] == "sqlite" ? "SQLite" : "PostgreSQL") +
         formatted("first import: %.0f instances/s (median of %d; target >= 2000)\n",
                   figures["first_import_per_s"].get<double>(), runs) +
         formatted("re-import:    %.0f instances/s (median of %d; target >= 5000)\n",
                   figures["reimport_per_s"].get<double>(), runs) +
         formatted("ratio re-import / first: %.2f\n", figures["reimport_to_first_ratio"].get<double>());
}

}  // namespace maxillo::bench
