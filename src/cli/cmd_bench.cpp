// maxillo bench import [--count 2000] [--workdir DIR] [--runs 3]: import throughput.
// Writes `count` 256x256 CT files (series of 200 slices) with the series writer, imports them
// into a fresh archive (hashing, parsing, durable objects and rows included) and re-imports
// them; prints the median instances/s of each and their ratio.
// Targets on the 2-core reference machine: >= 2000/s first import, >= 5000/s re-import.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "archive/archive.h"
#include "archive/dicom_series_writer.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

struct BenchArguments {
  int count = 2000;
  int runs = 3;
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

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double timed_import(Archive& archive, const std::vector<std::filesystem::path>& inputs, size_t expected_imported,
                    size_t expected_known) {
  ImportOptions options;
  options.progress = ProgressDisplay::Never;
  auto start = std::chrono::steady_clock::now();
  ImportReport report = archive.import_paths(inputs, options);
  double seconds = seconds_since(start);
  if (report.imported != expected_imported || report.already_archived != expected_known || !report.all_ok())
    throw Error(ErrorCode::kProcessing, archive.folder().string(), "benchmark import did not give the expected counts");
  return double(report.files()) / seconds;
}

void run_bench(const BenchArguments& args, CommandContext& ctx) {
  auto workdir = args.workdir.empty() ? std::filesystem::temp_directory_path() / "maxillo-bench" : args.workdir;
  std::filesystem::remove_all(workdir);
  auto start = std::chrono::steady_clock::now();
  auto inputs = generate_files(workdir / "input", args.count);
  double generate_seconds = seconds_since(start);

  std::vector<double> first, again;
  for (int run = 0; run < args.runs; ++run) {
    auto archive_folder = workdir / ("archive" + std::to_string(run));
    Archive archive = Archive::open(archive_folder, OpenMode::CreateIfMissing);
    first.push_back(timed_import(archive, inputs, size_t(args.count), 0));
    again.push_back(timed_import(archive, inputs, 0, size_t(args.count)));
    if (run + 1 < args.runs) std::filesystem::remove_all(archive_folder);
  }
  double first_rate = median(first), again_rate = median(again);
  if (ctx.global.json) {
    std::cout << Json{{"count", args.count},
                      {"runs", args.runs},
                      {"generate_seconds", generate_seconds},
                      {"first_import_per_s", first_rate},
                      {"reimport_per_s", again_rate},
                      {"first_import_runs_per_s", first},
                      {"reimport_runs_per_s", again},
                      {"reimport_to_first_ratio", again_rate / first_rate}}
                     .dump(2)
              << "\n";
  } else {
    std::printf("generated %d files of 256x256 in %.2f s\n", args.count, generate_seconds);
    std::printf("first import: %.0f instances/s (median of %d; target >= 2000)\n", first_rate, args.runs);
    std::printf("re-import:    %.0f instances/s (median of %d; target >= 5000)\n", again_rate, args.runs);
    std::printf("ratio re-import / first: %.2f\n", again_rate / first_rate);
  }
  std::filesystem::remove_all(workdir);
}

}  // namespace

void attach_bench_cube(CLI::App& bench, CommandContext& ctx);  // cmd_bench_cube.cpp
void attach_bench_occlusion(CLI::App& bench, CommandContext& ctx);  // cmd_bench_occlusion.cpp
void attach_bench_face(CLI::App& bench, CommandContext& ctx);       // cmd_bench_face.cpp
void attach_bench_register(CLI::App& bench, CommandContext& ctx);   // cmd_bench_register.cpp
void attach_bench_surfaces(CLI::App& bench, CommandContext& ctx);   // cmd_bench_surfaces.cpp

void attach_bench(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);
  CLI::App* import = app.add_subcommand("import", "import throughput (instances/s), first import and re-import");
  auto args = std::make_shared<BenchArguments>();
  import->add_option("--count", args->count, "number of 256x256 CT files")->check(CLI::Range(1, 1000000));
  import->add_option("--runs", args->runs, "runs; the median is reported")->check(CLI::Range(1, 50));
  import->add_option("--workdir", args->workdir, "scratch folder (default: $TMPDIR/maxillo-bench; emptied)");
  import->callback([args, &ctx] { run_bench(*args, ctx); });
  attach_bench_cube(app, ctx);
  attach_bench_occlusion(app, ctx);
  attach_bench_face(app, ctx);
  attach_bench_register(app, ctx);
  attach_bench_surfaces(app, ctx);
}

}  // namespace maxillo::cli
