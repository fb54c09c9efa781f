// Archive::verify: check the index (SQLite's integrity check and its journal), re-hash every
// indexed object, find missing, corrupt, orphan and temporary files. Repair never deletes: it
// quarantines orphans and temporaries and refuses when what it sees means a lost index.

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <unordered_set>

#include "archive/archive_sql.h"
#include "archive/archive_state.h"
#include "archive/index_comparison.h"
#include "archive/journal_replay.h"
#include "archive/journalled_transaction.h"
#include "archive/object_adoption.h"
#include "core/atomic_file.h"
#include "core/sha256.h"

namespace maxillo {
namespace {

// Orphans beyond this share of the store (and kManyOrphans files) are not what interrupted
// writes leave behind: an import batch is 500 files, but a store is normally thousands.
constexpr size_t kManyOrphans = 10;
constexpr size_t kOrphanShareDivisor = 20;  // 5 %

std::string integrity_check(db::Connection& db) {
  // A server checks its pages as it reads them; the journal comparison below reads every row.
  try {
    return db.integrity_check();
  } catch (const Error& e) {
    return e.reason();
  }
}

// Replays entries 1..N (N: the index's counter) into a scratch index in memory and compares it
// with the index row by row. The caller holds the store lock exclusively, so no writer commits
// meanwhile. In memory, not on disk: a check that needs disk space read a full disk as a
// damaged index (issue 29, fault 5). A check that cannot run says so in `failure`.
std::vector<std::string> journal_differences(Archive::State& state, std::string& failure) {
  std::vector<std::string> differences;
  try {
    sqlite::Database db(":memory:", sqlite::OpenKind::Create);
    upgrade_schema(db, state.journal);
    auto outcome = replay_journal(db, state.journal, journal_sequence(state.db));
    for (auto& problem : outcome.problems) differences.push_back("journal " + problem);
    std::vector<TableDifference> found;
    if (state.location.embedded()) {
      db::Statement attach(db, "ATTACH DATABASE ?1 AS live");
      attach.bind(1, index_file(state.location.folder).string()).run();
      found = compare_attached_indexes(db, "live");
    } else {
      found = compare_indexes(db, state.db);
    }
    for (const auto& difference : found)
      differences.push_back("index and journal differ in " + difference.describe() +
                            " (first: the journal's replay, second: the index)");
  } catch (const Error& e) {
    failure = e.reason();
  }
  return differences;
}

std::vector<std::string> owners_of(db::Connection& db, const std::string& sha) {
  db::Statement query(db, sql::kOwnersOfObject);
  query.bind(1, sha);
  std::vector<std::string> owners;
  while (query.step()) owners.push_back(query.text(0));
  return owners;
}

void scan_objects(Archive::State& state, ProgressDisplay display, VerifyReport& report) {
  std::unordered_map<std::string, int64_t> indexed;  // sha256 -> size
  {
    db::Statement query(state.db, sql::kAllObjects);
    while (query.step()) indexed.emplace(query.text(0), query.integer(1));
  }
  Progress progress("verify", indexed.size(), display);
  std::unordered_set<std::string> seen;
  state.objects.for_each_file(
      [&](ObjectStore::EntryKind kind, const std::string& sha, const std::filesystem::path& path) {
        if (kind == ObjectStore::EntryKind::Temporary) {
          report.temporaries.push_back(path);
          return;
        }
        auto found = indexed.find(sha);
        if (found == indexed.end()) {
          report.orphans.push_back(path);
          return;
        }
        seen.insert(sha);
        ++report.objects_checked;
        progress.advance();
        try {
          auto bytes = read_file(path);
          if (int64_t(bytes.size()) != found->second || sha256_hex(bytes) != sha) report.corrupt.push_back(sha);
        } catch (const Error&) {
          report.corrupt.push_back(sha);
        }
      });
  for (const auto& [sha, size] : indexed)
    if (!seen.contains(sha)) report.missing.push_back(sha);
  progress.finish();
  for (const auto* bad : {&report.missing, &report.corrupt})
    for (const auto& sha : *bad) report.owners[sha] = owners_of(state.db, sha);
}

}  // namespace

bool VerifyReport::leftovers_are_few() const {
  const size_t stored = objects_checked + orphans.size();
  return orphans.size() < kManyOrphans || orphans.size() * kOrphanShareDivisor <= stored;
}

namespace {

std::string reason_to_refuse(const VerifyReport& report, bool force) {
  if (!report.index_intact())
    return "the index is damaged or disagrees with its journal, so objects it does not name may still be data: "
           "run `maxillo archive rebuild-index` first";
  if (!report.journal_check_failure.empty())
    return "the index could not be compared with its journal (" + report.journal_check_failure +
           "), so objects it does not name may still be data";
  const size_t stored = report.objects_checked + report.orphans.size();
  if (!force && !report.leftovers_are_few())
    return std::to_string(report.orphans.size()) + " of " + std::to_string(stored) +
           " objects are named by no index row, more than interrupted writes leave behind. If a large import was "
           "interrupted, run it again (it adopts its objects); if the index was replaced by an older copy, run "
           "`maxillo archive rebuild-index`; to quarantine them anyway, repeat with --force (the quarantine keeps "
           "them until `verify --purge`)";
  return {};
}

bool younger_than(const std::filesystem::path& path, int64_t seconds) {
  if (seconds <= 0) return false;
  std::error_code error;
  const auto written = std::filesystem::last_write_time(path, error);
  if (error) return false;
  return std::filesystem::file_time_type::clock::now() - written < std::chrono::seconds(seconds);
}

void repair(Archive::State& state, const VerifyOptions& options, VerifyReport& report) {
  report.repair_refused = reason_to_refuse(report, options.force);
  if (!report.repair_refused.empty()) return;
  const int64_t grace = options.grace_seconds >= 0  ? options.grace_seconds
                        : state.location.embedded() ? 0
                                                    : kServerOrphanGraceSeconds;
  // Orphan DICOM objects are what an interrupted import left: adopted, as importing their files
  // again would. Other orphans and every temporary file go into the quarantine.
  std::vector<std::filesystem::path> orphans, set_aside = report.temporaries;
  for (const auto& path : report.orphans) {
    if (younger_than(path, grace))
      ++report.within_grace;
    else
      orphans.push_back(path);
  }
  auto adoption = adopt_objects(state.db, state.objects, state.journal, std::move(orphans), "verify --repair");
  report.adopted = std::move(adoption.adopted);
  set_aside.insert(set_aside.end(), adoption.not_adopted.begin(), adoption.not_adopted.end());
  for (const auto& path : set_aside) {
    if (younger_than(path, grace)) {
      ++report.within_grace;
      continue;
    }
    state.objects.set_aside(path);
    ++report.quarantined;
  }
  std::vector<std::string> still_missing;
  for (const auto& sha : report.missing) {
    if (state.objects.restore_from_quarantine(sha))
      report.restored.push_back(sha);
    else
      still_missing.push_back(sha);
  }
  report.missing = std::move(still_missing);
  if (report.quarantined > 0 || !report.restored.empty()) state.objects.make_durable();
  std::erase_if(report.orphans, [&](const auto& path) {  // what is adopted is an orphan no more
    return std::find(report.adopted.begin(), report.adopted.end(), path) != report.adopted.end();
  });
}

}  // namespace

VerifyReport Archive::verify(const VerifyOptions& options) {
  // Exclusive: no writer is between writing an object and committing its row, and no index
  // row changes while the index is compared with its journal.
  StoreLock lock(*state_, LockKind::Exclusive);
  VerifyReport report;
  report.index_check = integrity_check(state_->db);
  report.journal_differences = journal_differences(*state_, report.journal_check_failure);
  scan_objects(*state_, options.progress, report);
  if (options.mode == RepairMode::Repair) repair(*state_, options, report);
  return report;
}

size_t Archive::purge_quarantine() {
  StoreLock lock(*state_, LockKind::Exclusive);
  return state_->objects.purge_quarantine();
}

}  // namespace maxillo
