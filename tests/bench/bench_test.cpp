// The benchmarks at toy sizes: the figures they report and the lines `maxillo bench` prints
// from them. The times themselves are not tested (speed is what the benchmarks measure).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "bench/claim_benchmark.h"
#include "bench/cube_benchmark.h"
#include "bench/formatted.h"
#include "bench/import_benchmark.h"
#include "bench/index_benchmark.h"
#include "bench/landmark_benchmark.h"
#include "bench/dental_benchmark.h"
#include "bench/occlusion_benchmark.h"
#include "bench/register_benchmark.h"
#include "bench/timing.h"
#include "core/error.h"
#include "support/temporary_folder.h"

namespace maxillo::bench {
namespace {

using testing::TemporaryFolder;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(BenchTiming, TheMedianIsOneRunsOwnFigure) {
  EXPECT_EQ(median({3, 1, 2}), 2);
  EXPECT_EQ(median({4, 1, 3, 2}), 3);  // the upper of the two middle ones
  EXPECT_EQ(median({5}), 5);
}

TEST(BenchFormatted, FormatsAsPrintfDoesWhateverTheLength) {
  EXPECT_EQ(formatted("%-6s|%5.2f|%lld", "ab", 3.14159, 42LL), "ab    | 3.14|42");
  EXPECT_EQ(formatted("%s", std::string(5000, 'x').c_str()).size(), 5000u);
  EXPECT_EQ(formatted("%s", ""), "");
}

TEST(ClaimBenchmark, EveryItemIsClaimedOnceAndTheLineSaysHowFast) {
  TemporaryFolder folder;
  ClaimBenchOptions options;
  options.items = 30, options.workers = 2, options.runs = 1, options.workdir = folder.path();
  const Json figures = run_claim_benchmark(options);
  EXPECT_EQ(figures["items"], 30);
  EXPECT_EQ(figures["index"], "SQLite");
  EXPECT_GT(figures["claims_per_s"].get<double>(), 0);
  EXPECT_EQ(figures["runs_claims_per_s"].size(), 1u);
  const std::string text = claim_benchmark_text(figures);
  EXPECT_EQ(text.rfind("30 items, 2 workers at once, index on SQLite: ", 0), 0u) << text;
  EXPECT_NE(text.find(" claims/s (claim + finish; median of 1)\n"), std::string::npos) << text;
}

TEST(ImportBenchmark, FirstImportAndReimportInFourLines) {
  TemporaryFolder folder;
  ImportBenchOptions options;
  options.count = 12, options.runs = 1, options.workdir = folder / "work";
  const Json figures = run_import_benchmark(options);
  EXPECT_EQ(figures["index"], "sqlite");
  EXPECT_GT(figures["first_import_per_s"].get<double>(), 0);
  EXPECT_GT(figures["reimport_per_s"].get<double>(), 0);
  EXPECT_FALSE(std::filesystem::exists(folder / "work"));  // the scratch folder is removed
  const auto lines = lines_of(import_benchmark_text(figures));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0].rfind("generated 12 files of 256x256 in ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("; 1 importer(s) at once, index on SQLite"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[3].rfind("ratio re-import / first: ", 0), 0u) << lines[3];
}

// Issue 31: several numbers of importers, on disjoint and on overlapping inputs, as one table;
// overlapping inputs archive each instance once (the run throws when the counts are not so).
TEST(ImportBenchmark, WorkersAndInputsMakeATableWithTheClientsCpuTime) {
  TemporaryFolder folder;
  ImportBenchOptions options;
  options.count = 12, options.runs = 1, options.workdir = folder / "work";
  const std::vector<Json> runs = run_import_benchmarks(options, {1, 2}, {false, true});
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[3]["workers"], 2);
  EXPECT_EQ(runs[3]["inputs"], "overlapping");
  EXPECT_GT(runs[3]["client_cpu_seconds"].get<double>(), 0);
  EXPECT_TRUE(runs[3]["server_cpu_seconds"].is_null());  // SQLite: no server
  const auto lines = lines_of(import_benchmark_table(runs));
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "12 files of 256x256, index on SQLite, median of 1 run(s)");
  EXPECT_EQ(lines[5].rfind("      2  overlapping  ", 0), 0u) << lines[5];
}

// Issue 29, fault 14: a login the server refuses left the work folder behind.
TEST(ImportBenchmark, AFailedRunLeavesNoWorkFolderBehind) {
  TemporaryFolder folder;
  ImportBenchOptions options;
  options.count = 3, options.runs = 1, options.workdir = folder / "work";
  options.postgres = "postgresql://no_such_role@127.0.0.1:1/";  // nothing listens on port 1
  EXPECT_THROW(run_import_benchmark(options), Error);
  EXPECT_FALSE(std::filesystem::exists(folder / "work"));
}

TEST(IndexBenchmark, TimesEveryQueryAndGivesTheNightlyScanItsFolder) {
  TemporaryFolder folder;
  IndexBenchOptions options;
  options.patients = 4, options.instances = 16, options.runs = 2, options.workdir = folder.path();
  std::vector<std::filesystem::path> scanned;
  const Json figures = run_index_benchmark(options, [&](Archive& archive, const std::filesystem::path& out) {
    scanned.push_back(out);
    return archive.cases().size();
  });
  EXPECT_EQ(scanned, std::vector<std::filesystem::path>(2, folder / "nightly"));
  EXPECT_EQ(figures["eligible_cases"], 4);
  EXPECT_EQ(figures["median_seconds"].size(), 5u);
  const auto lines = lines_of(index_benchmark_text(figures, options.runs));
  ASSERT_EQ(lines.size(), 7u);
  EXPECT_EQ(lines[0].rfind("4 patients, 16 instances on SQLite (filled in ", 0), 0u) << lines[0];
  const char* order[] = {"list patients", "list series", "show case", "resolve Patient ID", "nightly scan"};
  for (int q = 0; q < 5; ++q) {
    EXPECT_EQ(lines[size_t(q + 1)].rfind(std::string("  ") + order[q], 0), 0u) << lines[size_t(q + 1)];
    EXPECT_NE(lines[size_t(q + 1)].find(" s (median of 2)"), std::string::npos) << lines[size_t(q + 1)];
  }
  EXPECT_EQ(lines[6], "  nightly scan found 4 eligible cases");
}

// CalculiX on the same small cube: its answer matches the FEM's at the bench's tolerance, and the
// figures say how long it took and the ratio of the times.
TEST(CubeBenchmark, CalculixSolvesTheSameCubeAsTheFem) {
  CubeBenchOptions options;
  options.tets = 3000, options.runs = 1, options.calculix = true;
  const Json figures = run_cube_benchmark(options);
  const Json& fem = figures["model_result"];
  EXPECT_LT(fem["calculix_vs_fem_worst_mm"].get<double>(), 1e-4);
  EXPECT_GT(fem["calculix_seconds"].get<double>(), 0);
  EXPECT_GT(fem["fem_speedup_over_calculix"].get<double>(), 0);
  EXPECT_NE(cube_benchmark_text(figures).find("\ncalculix_vs_fem_worst_mm: "), std::string::npos);
}

TEST(CubeBenchmark, MassTensorFiguresAndItsThresholdTable) {
  CubeBenchOptions options;
  options.tets = 400, options.model = softtissue::SoftTissueModel::kMassTensor, options.runs = 1;
  const Json figures = run_cube_benchmark(options);
  EXPECT_EQ(figures["model"], "mtm");
  EXPECT_EQ(figures["model_result"]["threshold_table"].size(), 5u);
  const std::string text = cube_benchmark_text(figures);
  EXPECT_NE(text.find("model: \"mtm\"\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nprecompute_seconds: "), std::string::npos) << text;
  EXPECT_EQ(text.find("threshold_table"), std::string::npos) << text;  // a table, not a key
  const auto lines = lines_of(text);
  ASSERT_GE(lines.size(), 6u);
  EXPECT_EQ(lines[lines.size() - 6].rfind("G_thresh", 0), 0u) << text;
  EXPECT_EQ(lines.back().rfind("1e-04 ", 0), 0u) << text;
}

TEST(RealDataBenchmarks, SayWhyTheySkipWithoutTheirData) {
  OcclusionBenchOptions occlusion;
  occlusion.data = "/nonexistent";
  EXPECT_EQ(occlusion_benchmark_text(run_occlusion_benchmark(occlusion)),
            "skipped: the real teeth are not at /nonexistent (set MAXILLO_SHARED_DATA or --data to the folder "
            "holding openfulljaw-p26-teeth)\n");
  DentalBenchOptions dental;
  dental.data = "/nonexistent";
  EXPECT_EQ(dental_benchmark_text(run_dental_benchmark(dental)),
            "skipped: the real teeth are not at /nonexistent (set MAXILLO_SHARED_DATA or --data to the folder "
            "holding openfulljaw-p26-teeth)\n");
  RegisterBenchOptions registration;
  registration.data = "/nonexistent";
  EXPECT_EQ(register_benchmark_text(run_register_benchmark(registration)),
            "skipped: the cadaver head CT is not at /nonexistent/slices (set MAXILLO_SHARED_DATA or --data to the "
            "folder holding cthead-stanford)\n");
}

}  // namespace
}  // namespace maxillo::bench

namespace maxillo::bench {
namespace {

// Two scans' outcomes with known errors: the P95 counts every detection, flagged ones too; the
// unflagged P95 only those a planner would use without a person's confirmation.
TEST(LandmarkBenchmark, FlaggedDetectionsCountInTheP95AndAreLeftOutOfTheUnflaggedOne) {
  std::vector<ScanRun> runs(2);
  auto outcome = [](bool has_truth, bool detected, bool flagged, double error_mm) {
    LandmarkOutcome o;
    o.has_truth = has_truth, o.detected = detected, o.flagged = flagged, o.error_mm = error_mm;
    return o;
  };
  runs[0].landmarks["OrL"] = outcome(true, true, false, 1.0);
  runs[1].landmarks["OrL"] = outcome(true, true, true, 11.0);
  runs[0].landmarks["N"] = outcome(true, false, false, 0);
  runs[1].landmarks["N"] = outcome(false, true, false, 0);
  const Json figures = landmark_benchmark_json(runs);
  const Json& orl = figures["landmarks"]["OrL"];
  EXPECT_EQ(orl["found"].get<int>(), 2);
  EXPECT_EQ(orl["flagged"].get<int>(), 1);
  EXPECT_NEAR(orl["p95_mm"].get<double>(), 10.5, 1e-9);  // linear between 1 and 11
  EXPECT_EQ(orl["unflagged"].get<int>(), 1);
  EXPECT_NEAR(orl["p95_unflagged_mm"].get<double>(), 1.0, 1e-9);
  const Json& n = figures["landmarks"]["N"];
  EXPECT_EQ(n["missed"].get<int>(), 1);
  EXPECT_EQ(n["invented"].get<int>(), 1);
  EXPECT_EQ(n["unflagged"].get<int>(), 0);
  const Json& second_scan = figures["scans"][1]["landmarks"];  // each scan's own outcomes too
  EXPECT_NEAR(second_scan["OrL"]["error_mm"].get<double>(), 11.0, 1e-9);
  EXPECT_TRUE(second_scan["OrL"]["flagged"].get<bool>());
  EXPECT_FALSE(second_scan["N"].contains("error_mm"));  // invented: no truth to measure against
  const std::string text = landmark_benchmark_text(runs);
  EXPECT_NE(text.find("unflagged P95"), std::string::npos) << text;
  EXPECT_NE(text.find("1.00 (1)"), std::string::npos) << text;
}

}  // namespace
}  // namespace maxillo::bench
