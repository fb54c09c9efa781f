#include "nightly/nightly.h"

#include <charconv>
#include <chrono>
#include <map>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/sha256.h"
#include "core/version.h"
#include "nightly/nightly_summary.h"
#include "nightly/nightly_worker.h"
#include "records/validation_archive.h"
#include "casework/validation/validation_json.h"

namespace maxillo::nightly {
namespace {

std::string text_of(const std::vector<std::byte>& bytes) {
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

// The work queue as the summary reads it: what the workers left of each item, and when.
struct WorkQueueState {
  std::map<std::string, WorkRecord> records;  // by item
  int64_t now = 0;                            // the index's clock
};

WorkQueueState read_work_queue(Archive& archive) {
  const WorkQueue queue(archive, kNightlyQueue);
  WorkQueueState state;
  for (auto& record : queue.records()) state.records.emplace(record.item, std::move(record));
  state.now = queue.clock_seconds();
  return state;
}

struct EligibleCase {
  int64_t case_id = 0;
  std::string key;  // validation inputs hash
};

// The cases of this shard, by case id. Whether each is eligible is decided case by case, so
// that a case whose records cannot be read fails alone (run_nightly).
std::vector<int64_t> shard_cases(const Archive& archive, const NightlyOptions& options) {
  std::map<int64_t, std::string> patient_ids;
  for (const auto& p : archive.patients()) patient_ids[p.id] = p.patient_id;
  std::vector<int64_t> cases;
  for (const auto& c : archive.cases())
    if (shard_of(patient_ids[c.patient], c.label, options.shard.count) == options.shard.index) cases.push_back(c.id);
  std::sort(cases.begin(), cases.end());
  return cases;
}

// Validates the case unless `stored` holds its up-to-date validation; fills `stored` with the
// validation made.
NightlyCase process_case(Archive& archive, const EligibleCase& c, const NightlyOptions& options,
                         const WorkQueueState& queue, std::optional<records::StoredValidation>& stored) {
  NightlyCase result;
  result.case_id = c.case_id;
  if (stored) {
    result.outcome = NightlyOutcome::kUpToDate;
    return result;
  }
  if (options.summary_only) {
    const auto record = queue.records.find(nightly_work_item(c.case_id, c.key));
    return unfinished_case(c.case_id, record == queue.records.end() ? nullptr : &record->second, queue.now);
  }
  const auto started = std::chrono::steady_clock::now();
  const auto validation = casework::validate_case(archive, c.case_id, options.validation,
                                                  options.out / ("case-" + std::to_string(c.case_id)));
  records::store_validation(archive, casework::validation_to_store(validation));
  stored = records::find_validation(archive, c.case_id, c.key);
  result.outcome = NightlyOutcome::kValidated;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

// One case of the run: nothing when it has no post-operative CT, plan or landmarks.
std::optional<NightlyCase> nightly_case(Archive& archive, int64_t case_id, const casework::CaseInputsHash& inputs,
                                        const NightlyOptions& options, const WorkQueueState& queue,
                                        std::vector<records::StoredValidation>& shown) {
  auto key = nightly_key(inputs);
  if (!key) return std::nullopt;
  const EligibleCase eligible{case_id, *key};
  auto stored = records::find_validation(archive, inputs.artefacts, eligible.key);
  NightlyCase result = process_case(archive, eligible, options, queue, stored);
  if (stored) shown.push_back(std::move(*stored));
  return result;
}

NightlyCase failed_case(int64_t case_id, std::string reason) {
  log::error("case ", case_id, ": validation failed: ", reason);
  return NightlyCase{case_id, NightlyOutcome::kFailed, std::move(reason), 0};
}

std::string summary_name(const Shard& shard) {
  if (shard.count == 1) return "validation-summary.pdf";
  return "validation-summary-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".pdf";
}

// What the summary states about the cases: the same whether they were validated tonight or earlier, so a run that
// changes nothing leaves the summary as it is.
std::vector<std::string> run_facts(const NightlyReport& report, const Shard& shard, size_t shown) {
  std::vector<std::string> facts{"Shard " + std::to_string(shard.index) + " of " + std::to_string(shard.count) + ": " +
                                 std::to_string(report.cases.size()) +
                                 " cases with a pre-operative CT, a post-operative CT and a plan; " +
                                 std::to_string(shown) + " with a validation of their current inputs, " +
                                 std::to_string(report.count(NightlyOutcome::kFailed)) + " failed."};
  for (const auto& c : report.cases)
    if (c.outcome == NightlyOutcome::kFailed || c.outcome == NightlyOutcome::kNotValidated)
      facts.push_back("case " + std::to_string(c.case_id) + ": " + c.reason);
  return facts;
}

// The summary's own key: the validations it shows and the program. Unchanged -> not rewritten.
std::string summary_key(const std::vector<records::StoredValidation>& shown, const std::vector<std::string>& facts) {
  Sha256 hash;
  for (const auto& v : shown) hash.update(v.record.inputs_hash + "\n");
  for (const auto& f : facts) hash.update(f + "\n");
  hash.update(kVersion);
  return hash.hex_digest();
}

}  // namespace

Shard parse_shard(std::string_view text) {
  Shard shard;
  const auto slash = text.find('/');
  auto number = [&](std::string_view part, int& value) {
    auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return error == std::errc{} && end == part.data() + part.size();
  };
  if (slash == std::string_view::npos || !number(text.substr(0, slash), shard.index) ||
      !number(text.substr(slash + 1), shard.count) || shard.count < 1 || shard.index < 1 || shard.index > shard.count)
    throw Error(ErrorCode::kBadValue, std::string(text),
                shard.index == 0 && shard.count >= 1
                    ? "shards are numbered from 1 (i/n with 1 <= i <= n): with a Slurm array, use --array=1-N, or "
                      "--shard $((SLURM_ARRAY_TASK_ID + 1))/$SLURM_ARRAY_TASK_COUNT for --array=0-(N-1)"
                    : "a shard is i/n with 1 <= i <= n, e.g. 2/8");
  return shard;
}

std::optional<std::string> nightly_key(const casework::CaseInputsHash& inputs) {
  if (inputs.error) try {
      std::rethrow_exception(inputs.error);
    } catch (const Error& e) {
      if (e.code() == ErrorCode::kNotFound) return std::nullopt;
      throw;
    }
  return inputs.hash;
}

int shard_of(const std::string& patient_id, const std::string& case_label, int count) {
  Sha256 hash;
  hash.update(patient_id + "\n" + case_label);
  const std::string digest = hash.hex_digest();
  return int(std::stoull(digest.substr(0, 12), nullptr, 16) % uint64_t(count)) + 1;
}

std::string_view to_string(NightlyOutcome outcome) {
  switch (outcome) {
    case NightlyOutcome::kValidated: return "validated";
    case NightlyOutcome::kUpToDate: return "up to date";
    case NightlyOutcome::kFailed: return "failed";
    case NightlyOutcome::kNotValidated: return "not validated";
  }
  return "?";
}

int NightlyReport::count(NightlyOutcome outcome) const {
  return int(std::count_if(cases.begin(), cases.end(), [&](const auto& c) { return c.outcome == outcome; }));
}

NightlyReport run_nightly(Archive& archive, const NightlyOptions& options) {
  if (options.claim && !options.summary_only) return run_nightly_worker(archive, options);
  std::filesystem::create_directories(options.out);
  NightlyReport report;
  std::vector<records::StoredValidation> shown;
  const auto cases = shard_cases(archive, options);
  const WorkQueueState queue = options.summary_only ? read_work_queue(archive) : WorkQueueState{};
  const auto inputs =
      casework::validation_inputs_hashes(archive, cases, options.validation);  // the scan: a few queries
  for (int64_t case_id : cases) {
    try {  // whatever one case throws, the others still run
      auto result = nightly_case(archive, case_id, inputs.at(case_id), options, queue, shown);
      if (!result) continue;
      report.cases.push_back(*result);
      log::info("case ", case_id, ": ", to_string(result->outcome));
    } catch (const Error& e) {
      report.cases.push_back(failed_case(case_id, e.what()));
    } catch (const std::exception& e) {
      report.cases.push_back(failed_case(case_id, std::string("internal error: ") + e.what()));
    } catch (...) {
      report.cases.push_back(failed_case(case_id, "internal error of an unknown kind"));
    }
  }
  report.summary_pdf = options.out / summary_name(options.shard);
  if (shown.empty()) return report;
  const auto facts = run_facts(report, options.shard, shown.size());
  const auto key = summary_key(shown, facts);
  const auto key_file = std::filesystem::path(report.summary_pdf).concat(".key");
  if (std::filesystem::exists(report.summary_pdf) && std::filesystem::exists(key_file) &&
      text_of(read_file(key_file)) == key)
    return report;
  report.summary_pages = write_validation_summary(shown, facts, report.summary_pdf);
  write_file_atomically(key_file, key);
  report.summary_written = true;
  return report;
}

}  // namespace maxillo::nightly
