// maxillo bench import [--count 2000] [--workdir DIR] [--runs 3] [--workers N] [--postgres URI]:
// import throughput, first import and re-import (bench/import_benchmark.h); and `bench` itself,
// which gathers the benchmarks' sub-commands.
#include <iostream>

#include "bench/import_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

void attach_bench_import(CLI::App& bench, CommandContext& ctx) {
  CLI::App* import = bench.add_subcommand("import", "import throughput (instances/s), first import and re-import");
  auto args = std::make_shared<bench::ImportBenchOptions>();
  import->add_option("--count", args->count, "number of 256x256 CT files")->check(CLI::Range(1, 1000000));
  import->add_option("--runs", args->runs, "runs; the median is reported")->check(CLI::Range(1, 50));
  import->add_option("--workers", args->workers, "importers at once into one archive (threads, own connections)")
      ->check(CLI::Range(1, 64));
  import->add_option("--postgres", args->postgres,
                     "the index on this PostgreSQL server, e.g. postgresql://postgres@127.0.0.1:5432/ (a database per "
                     "run is created and dropped)");
  import->add_option("--workdir", args->workdir, "scratch folder (default: $TMPDIR/maxillo-bench; emptied)");
  import->callback([args, &ctx] {
    const Json figures = bench::run_import_benchmark(*args);
  std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::import_benchmark_text(figures));
});
}  // namespace

}  // namespace maxillo::cli

void attach_bench_cube(CLI::App& bench, CommandContext& ctx);       // cmd_bench_cube.cpp
void attach_bench_occlusion(CLI::App& bench, CommandContext& ctx);  // cmd_bench_occlusion.cpp
void attach_bench_dental(CLI::App& bench, CommandContext& ctx);     // cmd_bench_dental.cpp
void attach_bench_face(CLI::App& bench, CommandContext& ctx);       // cmd_bench_face.cpp
void attach_bench_register(CLI::App& bench, CommandContext& ctx);   // cmd_bench_register.cpp
void attach_bench_surfaces(CLI::App& bench, CommandContext& ctx);   // cmd_bench_surfaces.cpp
void attach_bench_claim(CLI::App& bench, CommandContext& ctx);      // cmd_bench_claim.cpp
void attach_bench_index(CLI::App& bench, CommandContext& ctx);      // cmd_bench_index.cpp
void attach_bench_landmarks(CLI::App& bench, CommandContext& ctx);  // cmd_bench_landmarks.cpp

void attach_bench(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);
  attach_bench_import(app, ctx);
  attach_bench_cube(app, ctx);
  attach_bench_occlusion(app, ctx);
  attach_bench_dental(app, ctx);
  attach_bench_face(app, ctx);
  attach_bench_register(app, ctx);
  attach_bench_surfaces(app, ctx);
  attach_bench_claim(app, ctx);
  attach_bench_index(app, ctx);
  attach_bench_landmarks(app, ctx);
}

}  // namespace maxillo::cli
