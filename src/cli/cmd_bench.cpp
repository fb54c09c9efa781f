// maxillo bench import [--count 2000] [--workdir DIR] [--runs 3] [--workers N] [--postgres URI]:
// import throughput. Writes `count` 256x256 CT files (series of 200 slices) with the series
// writer, imports them into a fresh archive (hashing, parsing, durable objects and rows
// included) and re-imports them; prints the median instances/s of each and their ratio.
// --workers N: N importers at once (threads, each with its own connection), each given every
// N-th series, into one archive: the aggregate rate. --postgres postgresql://USER@HOST:PORT/:
// the index on that server instead of SQLite (a database per run, made and dropped here).
// Targets on the 2-core reference machine: >= 2000/s first import, >= 5000/s re-import.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "archive/archive.h"
#include "archive/dicom_series_writer.h"
#include "cli/bench_archive.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

struct BenchArguments {
  int count = 2000;
  int runs = 3;
  int workers = 1;
  std::string postgres;  // server address without a database; empty: SQLite
  std::filesystem::path workdir;
};

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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
  auto start = std::chrono::steady_clock::now();
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
  double seconds = seconds_since(start);
  for (auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  ImportReport total;
  for (const auto& r : reports) {
    total.imported += r.imported;
    total.already_archived += r.already_archived;
    total.conflicts += r.conflicts;
    total.failed += r.failed;
  }
  if (total.imported != expected_imported || total.already_archived != expected_known || !total.all_ok())
    throw Error(ErrorCode::kProcessing, address.string(), "benchmark import did not give the expected counts");
  return double(total.files()) / seconds;
}

void run_bench(const BenchArguments& args, CommandContext& ctx) {
  auto workdir = args.workdir.empty() ? std::filesystem::temp_directory_path() / "maxillo-bench" : args.workdir;
  std::filesystem::remove_all(workdir);
  auto start = std::chrono::steady_clock::now();
  auto inputs = generate_files(workdir / "input", args.count);
  double generate_seconds = seconds_since(start);

  std::vector<double> first, again;
  for (int run = 0; run < args.runs; ++run) {
    BenchArchive archive(args.postgres, workdir / ("archive" + std::to_string(run)), run);
    { Archive::open(archive.address(), OpenMode::CreateIfMissing); }
    first.push_back(timed_import(archive.address(), inputs, args.workers, size_t(args.count), 0));
    again.push_back(timed_import(archive.address(), inputs, args.workers, 0, size_t(args.count)));
  }
  double first_rate = median(first), again_rate = median(again);
  if (ctx.global.json) {
    std::cout << Json{{"count", args.count},
                      {"runs", args.runs},
                      {"workers", args.workers},
                      {"index", args.postgres.empty() ? "sqlite" : "postgresql"},
                      {"generate_seconds", generate_seconds},
                      {"first_import_per_s", first_rate},
                      {"reimport_per_s", again_rate},
                      {"first_import_runs_per_s", first},
                      {"reimport_runs_per_s", again},
                      {"reimport_to_first_ratio", again_rate / first_rate}}
                     .dump(2)
              << "\n";
  } else {
    std::printf("generated %d files of 256x256 in %.2f s; %d importer(s) at once, index on %s\n", args.count,
                generate_seconds, args.workers, args.postgres.empty() ? "SQLite" : "PostgreSQL");
    std::printf("first import: %.0f instances/s (median of %d; target >= 2000)\n", first_rate, args.runs);
    std::printf("re-import:    %.0f instances/s (median of %d; target >= 5000)\n", again_rate, args.runs);
    std::printf("ratio re-import / first: %.2f\n", again_rate / first_rate);
  }
  std::filesystem::remove_all(workdir);
}

}  // namespace

void attach_bench_cube(CLI::App& bench, CommandContext& ctx);       // cmd_bench_cube.cpp
void attach_bench_occlusion(CLI::App& bench, CommandContext& ctx);  // cmd_bench_occlusion.cpp
void attach_bench_face(CLI::App& bench, CommandContext& ctx);       // cmd_bench_face.cpp
void attach_bench_register(CLI::App& bench, CommandContext& ctx);   // cmd_bench_register.cpp
void attach_bench_surfaces(CLI::App& bench, CommandContext& ctx);   // cmd_bench_surfaces.cpp
void attach_bench_claim(CLI::App& bench, CommandContext& ctx);      // cmd_bench_claim.cpp
void attach_bench_index(CLI::App& bench, CommandContext& ctx);      // cmd_bench_index.cpp

void attach_bench(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);
  CLI::App* import = app.add_subcommand("import", "import throughput (instances/s), first import and re-import");
  auto args = std::make_shared<BenchArguments>();
  import->add_option("--count", args->count, "number of 256x256 CT files")->check(CLI::Range(1, 1000000));
  import->add_option("--runs", args->runs, "runs; the median is reported")->check(CLI::Range(1, 50));
  import->add_option("--workers", args->workers, "importers at once into one archive (threads, own connections)")
      ->check(CLI::Range(1, 64));
  import->add_option("--postgres", args->postgres,
                     "the index on this PostgreSQL server, e.g. postgresql://postgres@127.0.0.1:5432/ (a database per "
                     "run is created and dropped)");
  import->add_option("--workdir", args->workdir, "scratch folder (default: $TMPDIR/maxillo-bench; emptied)");
  import->callback([args, &ctx] { run_bench(*args, ctx);
});
attach_bench_cube(app, ctx);
attach_bench_occlusion(app, ctx);
attach_bench_face(app, ctx);
attach_bench_register(app, ctx);
attach_bench_surfaces(app, ctx);
attach_bench_claim(app, ctx);
attach_bench_index(app, ctx);
}  // namespace maxillo::cli

}  // namespace maxillo::cli
