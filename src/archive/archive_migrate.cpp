// Archive::migrate: an embedded archive copied into another archive (a PostgreSQL index with
// its shared object folder) by copying the objects and replaying the index journal.
#include "archive/archive_health.h"
#include "archive/archive_state.h"
#include "archive/index_comparison.h"
#include "archive/journal_replay.h"
#include "archive/journalled_transaction.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/sha256.h"
#include "dicom/dicom_header.h"

namespace maxillo {
namespace {

// The source, opened only to be read and held alone for the migration (no writer changes it
// meanwhile): its index file read-only with nothing made beside it, never upgraded.
struct Source {
  explicit Source(const std::filesystem::path& folder)
      : folder(folder),
        lock(folder, LockKind::Exclusive, StoreLock::LockFile::ExistingOnly),
        index(index_file(folder), sqlite::OpenKind::ReadOnlyUntouched),
        objects(objects_folder(folder)),
        journal(journal_folder(folder)) {}
  std::filesystem::path folder;
  StoreLock lock;
  sqlite::Database index;
  ObjectStore objects;
  IndexJournal journal;
};

void require_migratable(Source& source) {
  if (check_index_presence(source.folder) != IndexPresence::Present)
    throw Error(ErrorCode::kNotFound, source.folder.string(), "no archive index here to migrate");
  require_intact_index(source.index);
  if (source.index.schema_version() != Archive::newest_schema_version())
    throw Error(ErrorCode::kConflict, source.folder.string(),
                "the archive is at schema version " + std::to_string(source.index.schema_version()) +
                    "; open it once with this program (e.g. `maxillo --archive " + source.folder.string() +
                    " verify`) to upgrade it, then migrate");
  require_index_not_behind_journal(source.index, source.journal);
  const int64_t entries = journal_sequence(source.index);
  if (source.journal.has_pending(entries))
    throw Error(ErrorCode::kConflict, source.folder.string(),
                "its last journal entry is not yet marked committed (a writer stopped between its commit and the "
                "mark); open the archive once with this program (e.g. `maxillo --archive " +
                    source.folder.string() + " verify`), which marks it, then migrate");
}

// The target's history must be the start of the source's: a resumed migration, never another
// archive's.
void require_same_history(const Source& source, int64_t source_entries, Archive::State& target) {
  const int64_t target_entries = journal_sequence(target.db);
  const auto refuse = [&](const std::string& why) {
    throw Error(ErrorCode::kConflict, target.location.shown, "the target already holds another archive: " + why);
  };
  if (target_entries > source_entries)
    refuse("its index is at journal entry " + std::to_string(target_entries) + ", past the source's " +
           std::to_string(source_entries));
  // An entry not copied yet is what a killed migration leaves; one that differs is not.
  for (int64_t sequence = 1; sequence <= target_entries; ++sequence) {
    if (target.journal.has(sequence) &&
        journal_entry_text(target.journal.read(sequence)) != journal_entry_text(source.journal.read(sequence)))
      refuse("its journal entry " + std::to_string(sequence) + " differs from the source's");
  }
}

void copy_objects(Source& source, ObjectStore& target, ProgressDisplay display, MigrationReport& report) {
  std::vector<std::pair<std::string, std::filesystem::path>> objects;
  source.objects.for_each_file(
      [&](ObjectStore::EntryKind kind, const std::string& sha, const std::filesystem::path& path) {
        if (kind == ObjectStore::EntryKind::Object) objects.emplace_back(sha, path);
      });
  std::sort(objects.begin(), objects.end());
  Progress progress("copy objects", objects.size(), display);
  for (const auto& [sha, path] : objects) {
    progress.advance();
    if (target.state_of(sha) == ObjectStore::ObjectState::Intact) {
      ++report.objects_present;
      continue;
    }
    auto bytes = read_file(path);
    if (sha256_hex(bytes) != sha) {
      report.damaged_sources.push_back(path.string());
      continue;
    }
    target.put(sha, bytes);
    ++report.objects_copied;
  }
  progress.finish();
  target.make_durable();  // before any row naming them is committed
}

void copy_journal(const Source& source, int64_t entries, const IndexJournal& target, MigrationReport& report) {
  for (int64_t sequence = 1; sequence <= entries; ++sequence) {
    if (!source.journal.has(sequence)) {
      report.journal_problems.push_back("entry " + std::to_string(sequence) + ": missing in the source");
      continue;
    }
    target.write_committed(source.journal.read(sequence));  // durable before it returns
  }
}

// The de-identification secret travels with the archive: the same pseudonyms after the move.
void copy_secret(const Source& source, Archive& target) {
  const auto secret = source.folder / "deidentify.key";
  if (!std::filesystem::exists(secret)) return;
  const auto bytes = read_file(secret);
  const auto destination =
      target.embedded() ? target.folder() / "deidentify.key" : target.folder() / "settings" / "deidentify.key";
  if (std::filesystem::exists(destination)) {
    if (read_file(destination) != bytes)
      throw Error(ErrorCode::kConflict, destination.string(), "the target has another de-identification secret");
    return;
  }
  std::filesystem::create_directories(destination.parent_path());
  write_file_atomically(destination, bytes);
}

}  // namespace

MigrationReport Archive::migrate(const std::filesystem::path& source_folder,
                                 const std::filesystem::path& target_address, const MigrationOptions& options) {
  initialise_dicom_toolkit();
  if (names_index_server(source_folder.string()))
    throw Error(ErrorCode::kUsage, parse_archive_location(source_folder.string()).shown,
                "the source of a migration is an embedded archive (a folder)");
  Source source(source_folder);
  require_migratable(source);
  const int64_t entries = journal_sequence(source.index);

  Archive target = Archive::open(target_address, OpenMode::MigrationTarget);
  State& state = *target.state_;
  if (state.location.embedded() && std::filesystem::equivalent(state.location.folder, source.folder))
    throw Error(ErrorCode::kUsage, source_folder.string(), "the source and the target are the same archive");
  // Nothing else writes to the target while it is filled, on this node or any other.
  StoreLock lock(state, LockKind::Exclusive);
  require_same_history(source, entries, state);

  MigrationReport report;
  mark_migration_started(state.location.objects_folder(), std::filesystem::absolute(source_folder).string());
  // Objects first (durable before rows name them), then the rows, replayed from the source's
  // journal in one transaction, then the journal itself, entry by entry (each durable).
  copy_objects(source, state.objects, options.progress, report);
  auto replayed = replay_journal(state.db, source.journal, entries);
  copy_journal(source, entries, state.journal, report);
  report.journal_entries = replayed.entries;
  for (auto& problem : replayed.problems) report.journal_problems.push_back(std::move(problem));
  copy_secret(source, target);

  for (const auto& difference : compare_indexes(source.index, state.db))
    report.differences.push_back(difference.describe());
  for (const auto& table : index_tables()) {
    db::Statement count(state.db, "SELECT COUNT(*) FROM " + table);
    report.rows[table] = db::single_integer(count);
  }
  if (report.differences.empty() && report.journal_problems.empty() && report.damaged_sources.empty())
    mark_migration_finished(state.location.objects_folder());
  log::info("migrated ", report.journal_entries, " journal entries and ", report.objects_copied, " objects (",
            report.objects_present, " were already there)");
  return report;
}

}  // namespace maxillo
