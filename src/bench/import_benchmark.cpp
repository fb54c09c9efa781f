#include "bench/import_benchmark.h"

#include <sys/resource.h>

#include <algorithm>
#include <exception>
#include <optional>
#include <thread>
#include <vector>

#include "archive/archive.h"
#include "archive/server_cpu.h"
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

// CPU seconds (user and system) this process has used: every importer's threads.
double client_cpu_seconds() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) / 1e6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The index server's CPU seconds so far, when the archive's index is on a server of this machine.
std::optional<double> server_cpu_of(const std::filesystem::path& address) {
  const std::string text = address.string();
  if (!text.starts_with("postgresql://")) return std::nullopt;
  return server_cpu_seconds(text.substr(0, text.find('?')));
}

struct TimedImport {
  double per_s = 0;
  double client_cpu = 0;
  std::optional<double> server_cpu;
};

// Every worker imports its share (every N-th series folder, or with `overlapping` all of them)
// into the archive at `address`, all at once; returns the aggregate rate of `instances` (each
// counted once however many importers were given it) and the CPU time spent.
TimedImport timed_import(const std::filesystem::path& address, const std::vector<std::filesystem::path>& inputs,
                         int workers, bool overlapping, size_t instances, size_t expected_imported,
                         size_t expected_known) {
  ImportOptions options;
  options.progress = ProgressDisplay::Never;
  std::vector<ImportReport> reports(static_cast<size_t>(workers));
  std::vector<std::exception_ptr> failures(static_cast<size_t>(workers));
  std::vector<Archive> archives;
  for (int w = 0; w < workers; ++w) archives.push_back(Archive::open(address));
  const std::optional<double> server_before = server_cpu_of(address);
  const double client_before = client_cpu_seconds();
  const auto start = Clock::now();
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      std::vector<std::filesystem::path> share;
      const size_t step = overlapping ? 1 : size_t(workers);
      for (size_t n = overlapping ? 0 : size_t(w); n < inputs.size(); n += step) share.push_back(inputs[n]);
      try {
        reports[size_t(w)] = archives[size_t(w)].import_paths(share, options);
      } catch (...) {
        failures[size_t(w)] = std::current_exception();
      }
    });
  for (auto& thread : threads) thread.join();
  TimedImport timed;
  timed.per_s = double(instances) / seconds_since(start);
  timed.client_cpu = client_cpu_seconds() - client_before;
  if (const std::optional<double> server_after = server_cpu_of(address); server_before && server_after)
    timed.server_cpu = *server_after - *server_before;
  for (auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  // An import that did not give the expected counts is no measurement of import.
  const ImportReport total = added_up(reports);
  if (total.imported != expected_imported || total.already_archived != expected_known || !total.all_ok())
    throw Error(ErrorCode::kProcessing, address.string(), "benchmark import did not give the expected counts");
  return timed;
}

// The median of the runs' values, or null when a run has none.
Json median_or_null(const std::vector<std::optional<double>>& values) {
  std::vector<double> known;
  for (const auto& value : values)
    if (value) known.push_back(*value);
  if (known.empty() || known.size() != values.size()) return nullptr;
  return median(known);
}

// The runs of one number of workers and kind of input, on files already generated.
Json measure(const ImportBenchOptions& options, const std::filesystem::path& workdir,
             const std::vector<std::filesystem::path>& inputs, int workers, bool overlapping) {
  const size_t count = size_t(options.count);
  const size_t copies = overlapping ? size_t(workers) : 1;  // how many importers get each file
  std::vector<double> first, again, client_cpu;
  std::vector<std::optional<double>> server_cpu;
  for (int run = 0; run < options.runs; ++run) {
    ScratchArchive archive(options.postgres, workdir / ("archive" + std::to_string(run)), run);
    { Archive::open(archive.address(), OpenMode::CreateIfMissing); }
    const TimedImport timed =
        timed_import(archive.address(), inputs, workers, overlapping, count, count, count * (copies - 1));
    first.push_back(timed.per_s);
    client_cpu.push_back(timed.client_cpu);
    server_cpu.push_back(timed.server_cpu);
    again.push_back(timed_import(archive.address(), inputs, workers, overlapping, count, 0, count * copies).per_s);
  }
  const double first_rate = median(first), again_rate = median(again);
  return {{"count", options.count},
          {"runs", options.runs},
          {"workers", workers},
          {"inputs", overlapping ? "overlapping" : "disjoint"},
          {"index", options.postgres.empty() ? "sqlite" : "postgresql"},
          {"first_import_per_s", first_rate},
          {"reimport_per_s", again_rate},
          {"first_import_runs_per_s", first},
          {"reimport_runs_per_s", again},
          {"reimport_to_first_ratio", again_rate / first_rate},
          {"client_cpu_seconds", median(client_cpu)},
          {"server_cpu_seconds", median_or_null(server_cpu)}};
}

}  // namespace

std::vector<Json> run_import_benchmarks(const ImportBenchOptions& options, const std::vector<int>& workers,
                                        const std::vector<bool>& overlapping) {
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
  std::vector<Json> runs;
  for (const bool overlap : overlapping)
    for (const int n : workers) {
      runs.push_back(measure(options, workdir, inputs, n, overlap));
      runs.back()["generate_seconds"] = generate_seconds;
    }
  return runs;
}

Json run_import_benchmark(const ImportBenchOptions& options) {
  return run_import_benchmarks(options, {options.workers}, {options.overlapping}).front();
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

std::string import_benchmark_table(const std::vector<Json>& runs) {
  if (runs.empty()) return {};
  const Json& first = runs.front();
  std::string text = formatted("%d files of 256x256, index on %s, median of %d run(s)\n", first["count"].get<int>(),
                               first["index"] == "sqlite" ? "SQLite" : "PostgreSQL", first["runs"].get<int>());
  text += "workers  inputs       first import/s  re-import/s  client CPU s  server CPU s\n";
  for (const Json& run : runs) {
    const Json& server = run["server_cpu_seconds"];
    text += formatted("%7d  %-11s  %14.0f  %11.0f  %12.2f  %12s\n", run["workers"].get<int>(),
                      run["inputs"].get<std::string>().c_str(), run["first_import_per_s"].get<double>(),
                      run["reimport_per_s"].get<double>(), run["client_cpu_seconds"].get<double>(),
                      server.is_null() ? "-" : formatted("%.2f", server.get<double>()).c_str());
  }
  return text;
}

}  // namespace maxillo::bench
