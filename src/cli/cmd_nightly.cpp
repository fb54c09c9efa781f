// maxillo nightly --out DIR [--shard i/n | --claim [--lease S] [--worker NAME]] [--summary-only]: validate every
// case with a post-operative CT and a plan, skipping those up to date, and write the summary PDF.
#include <iostream>

#include "cli/command.h"
#include "core/error.h"
#include "nightly/nightly.h"

namespace maxillo::cli {
namespace {

struct NightlyArguments {
  std::filesystem::path out;
  std::string shard = "1/1";
  bool summary_only = false;
  bool no_correspondence = false;
  bool claim = false;
  int64_t lease_seconds = 600;
  std::string worker;
};

int run(const NightlyArguments& a, const GlobalOptions& global) {
  auto archive = Archive::open(resolve_archive_dir(global));
  nightly::NightlyOptions options;
  options.out = a.out;
  options.shard = nightly::parse_shard(a.shard);
  options.summary_only = a.summary_only;
  options.validation.corresponding_points = !a.no_correspondence;
  options.claim = a.claim;
  options.lease_seconds = a.lease_seconds;
  options.worker = a.worker;
  const auto report = nightly::run_nightly(archive, options);
  for (const auto& c : report.cases) {
    std::cout << "case " << c.case_id << ": " << nightly::to_string(c.outcome);
    if (c.outcome == nightly::NightlyOutcome::kValidated) std::cout << " (" << c.seconds << " s)";
    if (!c.reason.empty()) std::cout << ": " << c.reason;
    std::cout << "\n";
  }
  std::cout << report.count(nightly::NightlyOutcome::kValidated) << " validated, "
            << report.count(nightly::NightlyOutcome::kUpToDate) << " up to date, "
            << report.count(nightly::NightlyOutcome::kFailed) << " failed";
  const int left = report.count(nightly::NightlyOutcome::kNotValidated);
  if (left) std::cout << ", " << left << " not validated";
  std::cout << "\n";
  if (options.claim && !options.summary_only)
    std::cout << "worker done: every case is finished; `nightly --summary-only` writes the summary\n";
  else if (report.summary_written)
    std::cout << "wrote " << report.summary_pdf.string() << " (" << report.summary_pages << " pages)\n";
  else if (std::filesystem::exists(report.summary_pdf))
    std::cout << "summary up to date: " << report.summary_pdf.string() << "\n";
  else
    std::cout << "no validated case: no summary\n";
  // A summary that lists cases left unvalidated (a worker cancelled before the queue was done)
  // is a batch not finished either: exit 1, so a scheduler's job record says so.
  return report.count(nightly::NightlyOutcome::kFailed) || left ? exit_code_for(ErrorCode::kBatchPartlyFailed) : 0;
}

}  // namespace

void attach_nightly(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<NightlyArguments>();
  app.add_option("--out", a->out, "output folder: case-<id>/ folders and validation-summary.pdf")->required();
  auto shard = app.add_option("--shard", a->shard,
                              "run slice i of n, numbered from 1 (Slurm: sbatch --array=1-N with "
                              "--shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)")
                   ->capture_default_str();
  auto claim =
      app.add_flag("--claim", a->claim,
                   "claim cases one at a time from the archive's work queue with a lease, beside other workers "
                   "on any node; no summary (run --summary-only after the workers)")
          ->excludes(shard);
  app.add_option("--lease", a->lease_seconds, "with --claim: seconds before a dead worker's case is taken over")
      ->capture_default_str()
      ->check(CLI::Range(int64_t(5), int64_t(86400)))
      ->needs(claim);
  app.add_option("--worker", a->worker, "with --claim: this worker's name in the queue (default host:pid)")
      ->needs(claim);
  app.add_flag("--summary-only", a->summary_only, "validate nothing; summarise what the archive holds");
  app.add_flag("--no-correspondence", a->no_correspondence, "skip the corresponding-point distances");
  app.callback([a, &ctx] { ctx.exit_code = run(*a, ctx.global); });
}

}  // namespace maxillo::cli
