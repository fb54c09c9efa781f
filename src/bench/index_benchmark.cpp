#include "bench/index_benchmark.h"

#include <algorithm>
#include <array>

#include "archive/synthetic_index.h"
#include "bench/formatted.h"
#include "bench/scratch_archive.h"
#include "bench/timing.h"
#include "core/log.h"
#include "planning/plan.h"
#include "records/case_landmarks.h"
#include "records/plan_archive.h"

namespace maxillo::bench {
namespace {

// The queries users wait for, in the order they are timed and printed.
constexpr std::array<const char*, 5> kQueries = {"list patients", "list series", "show case", "resolve Patient ID",
                                                 "nightly scan"};

// Every case gets the same plan and landmarks (stored once: objects are content-addressed).
void make_every_case_eligible(Archive& archive) {
  const auto plan = planning::distraction_plan(planning::MaxillaryTarget{}, "bench");
  for (const auto& c : archive.cases()) {
    records::store_plan(archive, c.id, plan);
    records::attach_landmarks(archive, c.id, {{"S", {0, 0, 0}}, {"N", {0, -70, 10}}}, "bench");
  }
}

// The Patient ID the synthetic index gives patient `n`: P000001 and on.
std::string synthetic_patient_id(int64_t n) {
  const std::string digits = std::to_string(n);
  return "P" + std::string(6 - digits.size(), '0') + digits;
}

// The nightly scan without its line per case.
size_t quiet_scan(const NightlyScan& nightly_scan, Archive& archive, const std::filesystem::path& out) {
  const auto shown = log::level();
  log::set_level(std::min(shown, log::Level::Warning));
  const size_t eligible = nightly_scan(archive, out);
  log::set_level(shown);
  return eligible;
}

}  // namespace

Json run_index_benchmark(const IndexBenchOptions& options, const NightlyScan& nightly_scan) {
  const auto workdir =
      options.workdir.empty() ? std::filesystem::temp_directory_path() / "maxillo-bench-index" : options.workdir;
  ScratchArchive scratch(options.postgres, workdir / "archive", 0);
  const double fill_seconds = seconds_of([&] {
    fill_synthetic_index(scratch.address(), {options.patients, options.instances});
  });
  Archive archive = Archive::open(scratch.address());
  const double eligible_seconds = seconds_of([&] { make_every_case_eligible(archive); });
  const int64_t middle_case = archive.resolve_case(synthetic_patient_id(options.patients / 2));
  const std::string first_patient = synthetic_patient_id(1);
  size_t eligible = 0;
  const std::array<std::function<void()>, kQueries.size()> queries = {
      [&] { (void)archive.patients(); },
      [&] { (void)archive.series(); },
      [&] {
        auto contents = archive.case_contents(middle_case);
        for (const auto& member : contents.series) (void)archive.instances(member.series.id);
      },
      [&] { (void)archive.resolve(first_patient); },
      [&] { eligible = quiet_scan(nightly_scan, archive, workdir / "nightly"); },
  };
  Json timings = Json::object();
  for (size_t q = 0; q < kQueries.size(); ++q) timings[kQueries[q]] = median_seconds(options.runs, queries[q]);
  return {{"index", scratch.index_kind()},
          {"patients", options.patients},
          {"instances", options.instances},
          {"fill_seconds", fill_seconds},
          {"plans_and_landmarks_seconds", eligible_seconds},
          {"eligible_cases", eligible},
          {"median_seconds", timings}};
}

std::string index_benchmark_text(const Json& figures, int runs) {
  std::string text =
      formatted("%lld patients, %lld instances on %s (filled in %.1f s; plans and landmarks in %.1f s)\n",
                figures["patients"].get<long long>(), figures["instances"].get<long long>(),
                figures["index"].get<std::string>().c_str(), figures["fill_seconds"].get<double>(),
                figures["plans_and_landmarks_seconds"].get<double>());
  for (const char* query : kQueries)
    text += formatted("  %-20s %8.3f s (median of %d)\n", query, figures["median_seconds"][query].get<double>(), runs);
  return text + formatted("  nightly scan found %zu eligible cases\n", figures["eligible_cases"].get<size_t>());
}

}  // namespace maxillo::bench
