// maxillo bench index [--patients 1000] [--instances 500000] [--runs 5] [--postgres URI]:
// queries on an index of a hospital's size. Fills a scratch archive with synthetic rows in bulk
// (archive/synthetic_index.h: per patient a study, a pre- and a post-operative CT series, the
// default case), gives every case a plan and landmarks (so every case is eligible for the
// nightly validation), then times what users wait for: `list patients`, `list series`, `show`
// of one case, resolving a Patient ID, and the nightly scan (`nightly --summary-only` with
// nothing validated yet: every case's validation inputs hash and stored validation looked up,
// all `nightly` does before deciding what to validate). Medians of --runs.
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>

#include "archive/archive.h"
#include "archive/synthetic_index.h"
#include "cli/bench_archive.h"
#include "cli/command.h"
#include "core/json.h"
#include "core/log.h"
#include "records/case_landmarks.h"
#include "casework/case_validation.h"
#include "nightly/nightly.h"
#include "records/plan_archive.h"

namespace maxillo::cli {
namespace {

struct IndexArguments {
  int64_t patients = 1000;
  int64_t instances = 500000;
  int runs = 5;
  std::string postgres;
  std::filesystem::path workdir;
};

double seconds_of(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Every case gets the same plan and landmarks (stored once: objects are content-addressed).
void make_every_case_eligible(Archive& archive) {
  const auto plan = planning::distraction_plan(planning::MaxillaryTarget{}, "bench");
  for (const auto& c : archive.cases()) {
    records::store_plan(archive, c.id, plan);
    records::attach_landmarks(archive, c.id, {{"S", {0, 0, 0}}, {"N", {0, -70, 10}}}, "bench");
  }
}

void run_bench_index(const IndexArguments& args, CommandContext& ctx) {
  const auto workdir =
      args.workdir.empty() ? std::filesystem::temp_directory_path() / "maxillo-bench-index" : args.workdir;
  BenchArchive scratch(args.postgres, workdir / "archive", 0);
  const double fill_seconds = seconds_of([&] {
    fill_synthetic_index(scratch.address(), {args.patients, args.instances});
  });
  Archive archive = Archive::open(scratch.address());
  const double eligible_seconds = seconds_of([&] { make_every_case_eligible(archive); });
  const int64_t middle_case = archive.resolve_case(
      "P" + std::string(6 - std::to_string(args.patients / 2).size(), '0') + std::to_string(args.patients / 2));
  size_t eligible = 0;
  const std::vector<std::pair<std::string, std::function<void()>>> queries = {
      {"list patients", [&] { (void)archive.patients(); }},
      {"list series", [&] { (void)archive.series(); }},
      {"show case",
       [&] {
         auto contents = archive.case_contents(middle_case);
         for (const auto& member : contents.series) (void)archive.instances(member.series.id);
       }},
      {"resolve Patient ID", [&] { (void)archive.resolve("P000001"); }},
      {"nightly scan",
       [&] {  // `nightly --summary-only`: the scan of every case, nothing to validate or summarise
         nightly::NightlyOptions nightly;
         nightly.out = workdir / "nightly";
         nightly.summary_only = true;
         const auto shown = log::level();
         log::set_level(std::min(shown, log::Level::Warning));  // not a line per case
         eligible = nightly::run_nightly(archive, nightly).cases.size();
         log::set_level(shown);
       }},
  };
  Json timings = Json::object();
  for (const auto& [name, query] : queries) {
    std::vector<double> times;
    for (int run = 0; run < args.runs; ++run) times.push_back(seconds_of(query));
    timings[name] = median(times);
  }
  if (ctx.global.json) {
    std::cout << Json{{"index", scratch.engine()},
                      {"patients", args.patients},
                      {"instances", args.instances},
                      {"fill_seconds", fill_seconds},
                      {"plans_and_landmarks_seconds", eligible_seconds},
                      {"eligible_cases", eligible},
                      {"median_seconds", timings}}
                     .dump(2)
              << "\n";
    return;
  }
  std::printf("%lld patients, %lld instances on %s (filled in %.1f s; plans and landmarks in %.1f s)\n",
              static_cast<long long>(args.patients), static_cast<long long>(args.instances), scratch.engine(),
              fill_seconds, eligible_seconds);
  for (const auto& [name, query] : queries)
    std::printf("  %-20s %8.3f s (median of %d)\n", name.c_str(), timings[name].get<double>(), args.runs);
  std::printf("  nightly scan found %zu eligible cases\n", eligible);
}

}  // namespace

void attach_bench_index(CLI::App& bench, CommandContext& ctx) {
  CLI::App* index = bench.add_subcommand("index", "list, show and the nightly scan on a large synthetic index");
  auto args = std::make_shared<IndexArguments>();
  index->add_option("--patients", args->patients, "patients (each: a study, 2 CT series, a case)")
      ->check(CLI::Range(int64_t(1), int64_t(1000000)))
      ->capture_default_str();
  index->add_option("--instances", args->instances, "instances in all")
      ->check(CLI::Range(int64_t(2), int64_t(100000000)))
      ->capture_default_str();
  index->add_option("--runs", args->runs, "runs of each query; the median is reported")->check(CLI::Range(1, 50));
  index->add_option("--postgres", args->postgres,
                    "the index on this PostgreSQL server, e.g. postgresql://postgres@127.0.0.1:5432/ (a database is "
                    "created and dropped)");
  index->add_option("--workdir", args->workdir, "scratch folder (default: $TMPDIR/maxillo-bench-index; emptied)");
  index->callback([args, &ctx] { run_bench_index(*args, ctx); });
}

}  // namespace maxillo::cli
