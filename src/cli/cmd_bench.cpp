// maxillo bench import [--count 2000] [--workdir DIR] [--runs 3] [--workers 1,2,4] [--inputs disjoint,overlapping]
// [--postgres URI]:
// import throughput, first import and re-import (bench/import_benchmark.h); and `bench` itself,
// which gathers the benchmarks' sub-commands.
#include <iostream>
#include <string>
#include <vector>

#include "bench/import_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

// "1,2,4" and "disjoint,overlapping" as the benchmark takes them.
struct ImportBenchArgs {
  bench::ImportBenchOptions options;
  std::vector<int> workers{1};
  std::vector<std::string> inputs{"disjoint"};
};

void print_import_benchmarks(const ImportBenchArgs& args, const CommandContext& ctx) {
  std::vector<bool> overlapping;
  for (const auto& kind : args.inputs) overlapping.push_back(kind == "overlapping");
  const std::vector<Json> runs = bench::run_import_benchmarks(args.options, args.workers, overlapping);
  if (runs.size() == 1) {
    std::cout << (ctx.global.json ? json_text(runs.front()) + "\n" : bench::import_benchmark_text(runs.front()));
    return;
  }
  std::cout << (ctx.global.json ? json_text(Json(runs)) + "\n" : bench::import_benchmark_table(runs));
}

void attach_bench_import(CLI::App& bench, CommandContext& ctx) {
  CLI::App* import = bench.add_subcommand("import", "import throughput (instances/s), first import and re-import");
  auto args = std::make_shared<ImportBenchArgs>();
  import->add_option("--count", args->options.count, "number of 256x256 CT files")->check(CLI::Range(1, 1000000));
  import->add_option("--runs", args->options.runs, "runs; the median is reported")->check(CLI::Range(1, 50));
  import
      ->add_option("--workers", args->workers,
                   "importers at once into one archive (threads, own connections); a list (1,2,4) gives a table")
      ->delimiter(',')
      ->check(CLI::Range(1, 64));
  import
      ->add_option("--inputs", args->inputs,
                   "disjoint (each importer a share of the files), overlapping (every importer every file), or both "
                   "(disjoint,overlapping)")
      ->delimiter(',')
      ->check(CLI::IsMember({"disjoint", "overlapping"}));
  import->add_option("--postgres", args->options.postgres,
                     "the index on this PostgreSQL server, e.g. postgresql://postgres@127.0.0.1:5432/ (a database per "
                     "run is created and dropped)");
  import->add_option("--workdir", args->options.workdir, "scratch folder (default: $TMPDIR/maxillo-bench; emptied)");
  import->callback([args, &ctx] { print_import_benchmarks(*args, ctx);
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
