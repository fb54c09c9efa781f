#pragma once
// `maxillo nightly`: every case of the archive with a pre-operative CT, a post-operative CT and a plan validated
// (case_validation.h) and summarised in one PDF, as a job a scheduler runs.
//
// Incremental: a case whose validation is stored under its current inputs' hash (both series, the plan, the
// landmarks, the options, the program version) is skipped. Resumable: each case's results enter the archive when the
// case is done (validation_archive.h), so a run killed half-way resumes with the first case not done. A failing case
// is reported and the run goes on. Sharded: `--shard i/n` takes the cases whose key (a hash of Patient ID and case
// label, stable as cases are added) falls in slice i of n, so a Slurm array or a Kubernetes indexed Job can run the
// slices on many machines against one archive; `--summary-only` then writes the summary of every case from what the
// slices stored.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "archive/archive.h"
#include "casework/validation/case_validation.h"

namespace maxillo::nightly {

struct Shard {
  int index = 1;  // 1..count
  int count = 1;
};
// "i/n" with 1 <= i <= n. Error(kBadValue) otherwise.
Shard parse_shard(std::string_view text);
// Which slice (1..count) a case belongs to: stable for a given Patient ID and case label.
int shard_of(const std::string& patient_id, const std::string& case_label, int count);

struct NightlyOptions {
  std::filesystem::path out;  // per-case folders case-<id>/ and the summary PDF
  Shard shard;
  bool summary_only = false;  // validate nothing: summarise what is stored
  casework::ValidationOptions validation;
  // Claim cases from the archive's work queue instead of a static shard (nightly_worker.h).
  bool claim = false;
  std::string worker;                    // the lease holder's name; default host:pid
  int64_t lease_seconds = 600;           // a dead worker's case is taken over after this long
  std::chrono::milliseconds poll{1000};  // how often a worker with nothing to claim looks again
};

// Whether the nightly run validates a case, from the scan of every case (validation_inputs_hashes): its inputs hash,
// or nothing for a case without a post-operative CT, a plan, landmarks or images (Error(kNotFound): e.g. a follow-up
// cohort's case). Rethrows any other error of reading the case.
std::optional<std::string> nightly_key(const casework::CaseInputsHash& inputs);

enum class NightlyOutcome { kValidated, kUpToDate, kFailed, kNotValidated };
std::string_view to_string(NightlyOutcome outcome);

struct NightlyCase {
  int64_t case_id = 0;
  NightlyOutcome outcome = NightlyOutcome::kNotValidated;
  std::string reason;  // for kFailed: the error; for kNotValidated: why
  double seconds = 0;
};

struct NightlyReport {
  std::vector<NightlyCase> cases;  // the eligible cases of this shard, by case id
  std::filesystem::path summary_pdf;
  bool summary_written = false;  // false: the existing summary was up to date
  int summary_pages = 0;
  int count(NightlyOutcome outcome) const;
};

NightlyReport run_nightly(Archive& archive, const NightlyOptions& options);

}  // namespace maxillo::nightly
