// Archive::verify: re-hash every indexed object, find missing, corrupt, orphan and temporary
// files. Repair deletes orphans and temporaries only: a missing or corrupt object is data loss
// that a person must see, and its rows stay.
#include <unordered_map>
#include <unordered_set>

#include "archive/archive_sql.h"
#include "archive/archive_state.h"
#include "core/atomic_file.h"
#include "core/sha256.h"

namespace maxillo {

VerifyReport Archive::verify(RepairMode mode, ProgressDisplay display) {
  // Exclusive: no importer is between writing an object and committing its row, so every
  // unindexed object really is an orphan.
  StoreLock lock(state_->folder, LockKind::Exclusive);
  VerifyReport report;
  std::unordered_map<std::string, int64_t> indexed;  // sha256 -> size
  {
    sqlite::Statement query(state_->db, sql::kAllObjects);
    while (query.step()) indexed.emplace(query.text(0), query.integer(1));
  }
  Progress progress("verify", indexed.size(), display);
  std::unordered_set<std::string> seen;
  state_->objects.for_each_file([&](ObjectStore::EntryKind kind, const std::string& sha, const std::filesystem::path& path) {
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

  if (mode == RepairMode::Repair) {
    for (const auto* paths : {&report.orphans, &report.temporaries})
      for (const auto& path : *paths) {
        std::error_code error;
        if (std::filesystem::remove(path, error)) ++report.removed;
      }
    if (report.removed > 0) state_->objects.make_durable();
  }
  return report;
}

}  // namespace maxillo
