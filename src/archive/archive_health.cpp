#include "archive/archive_health.h"

#include "archive/archive_state.h"
#include "archive/sqlite.h"
#include "archive/journalled_transaction.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/utc_time.h"

namespace maxillo {
namespace {

std::string rebuild_advice(const std::filesystem::path& archive_folder) {
  return "rebuild it from the object store with `maxillo --archive " + archive_folder.string() +
         " archive rebuild-index` (nothing has been changed)";
}

std::string rebuild_advice(db::Connection& db) {
  if (const auto file = db.index_file(); !file.empty()) return rebuild_advice(file.parent_path());
  return "restore the database from its backup; the shared object folder and its journal are untouched";
}

}  // namespace

namespace {

std::filesystem::path migration_mark(const std::filesystem::path& objects_folder) {
  return objects_folder / "settings" / "migration-in-progress";
}

}  // namespace

void mark_migration_started(const std::filesystem::path& objects_folder, const std::string& source) {
  const auto mark = migration_mark(objects_folder);
  create_folders_durably(mark.parent_path());
  write_file_atomically(mark, source + "\n" + utc_now() + "\n");
}

void mark_migration_finished(const std::filesystem::path& objects_folder) {
  std::error_code ignored;
  std::filesystem::remove(migration_mark(objects_folder), ignored);
  sync_folder(migration_mark(objects_folder).parent_path());
}

void require_no_unfinished_migration(const std::filesystem::path& objects_folder, const std::string& shown) {
  const auto mark = migration_mark(objects_folder);
  std::error_code error;
  if (!std::filesystem::exists(mark, error)) return;
  std::string source = "its source";
  try {
    const auto bytes = read_file(mark);
    const std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    source = text.substr(0, text.find('\n'));
  } catch (const Error&) {}
  throw Error(ErrorCode::kConflict, shown,
              "a migration into this archive from " + source +
                  " has not finished (it was stopped, or its result did not verify); nothing here is complete. Run "
                  "`maxillo --archive " +
                  source + " archive migrate --to ADDRESS` again to finish it");
}

bool holds_any_file(const std::filesystem::path& folder) {
  std::error_code error;
  for (std::filesystem::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
    if (it->is_regular_file(error)) return true;
  return false;
}

IndexPresence check_index_presence(const std::filesystem::path& archive_folder) {
  auto index = index_file(archive_folder);
  std::error_code error;
  bool present = std::filesystem::exists(index, error) && std::filesystem::file_size(index, error) > 0 && !error;
  if (present) return IndexPresence::Present;
  if (!holds_any_file(objects_folder(archive_folder))) return IndexPresence::Fresh;
  throw Error(
      ErrorCode::kIndexDamaged, index.string(),
      std::string(std::filesystem::exists(index) ? "the index is empty" : "the index is missing") +
          " but the object store holds archived data; it is never re-created empty: " + rebuild_advice(archive_folder));
}

void require_intact_index(db::Connection& db) {
  // A PostgreSQL server checks its own pages as it reads them (and with data checksums on).
  const std::string first = db.quick_check();
  if (first == "ok") return;
  throw Error(ErrorCode::kIndexDamaged, db.name(),
              "the index is damaged (SQLite quick_check: " + first + "); " + rebuild_advice(db));
}

void require_index_not_behind_journal(db::Connection& db, const IndexJournal& journal) {
  // A committed entry N+1 is written only after N+1 has committed in some index, and the
  // counter never goes back, so if the counter is the same before and after looking, a
  // committed entry past it proves commits this index lacks.
  int64_t before = journal_sequence(db);
  for (int attempt = 0; attempt < 10; ++attempt) {
    bool ahead = journal.has(before + 1);
    int64_t after = journal_sequence(db);
    if (after != before) {
      before = after;  // another process committed meanwhile: look again
      continue;
    }
    if (!ahead) return;
    throw Error(ErrorCode::kIndexDamaged, db.name(),
                "the index is behind its journal (index at entry " + std::to_string(before) +
                    ", the journal holds committed entry " + std::to_string(before + 1) +
                    "): it was restored from an older copy or lost commits; " + rebuild_advice(db));
  }
}

}  // namespace maxillo
