// Archive::rebuild_index: a lost or damaged index re-created from the object store alone
// (the journal and the objects), built beside the old one and swapped in only when complete.
#include "archive/archive_health.h"
#include "archive/archive_state.h"
#include "archive/journal_replay.h"
#include "archive/journalled_transaction.h"
#include "archive/object_adoption.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/sha256.h"
#include "core/utc_time.h"
#include "dicom/dicom_header.h"

namespace maxillo {
namespace {

void remove_index_files(const std::filesystem::path& index) {
  std::error_code ignored;
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::filesystem::remove(index.string() + suffix, ignored);
}

// Whether the index as it stands would be accepted by Archive::open.
bool index_is_intact(const std::filesystem::path& folder, const IndexJournal& journal) {
  try {
    if (check_index_presence(folder) != IndexPresence::Present) return false;
    sqlite::Database db(index_file(folder), sqlite::OpenKind::Existing);
    require_intact_index(db);
    if (db.schema_version() >= 2) require_index_not_behind_journal(db, journal);
    return db.schema_version() >= 1;
  } catch (const Error&) {
    return false;
  }
}

void restore_named_objects(db::Connection& db, ObjectStore& objects, RebuildReport& report) {
  db::Statement query(db, "SELECT sha256 FROM objects");
  while (query.step()) {
    auto sha = query.text(0);
    if (objects.state_of(sha) == ObjectStore::ObjectState::Absent && objects.restore_from_quarantine(sha))
      ++report.restored_from_quarantine;
  }
}

// Every instance row against its object: the journal says what the index said, the object is
// the data, and they must agree.
void check_instances(db::Connection& db, const ObjectStore& objects, ProgressDisplay display, RebuildReport& report) {
  db::Statement count(db, "SELECT COUNT(*) FROM instances");
  count.step();
  Progress progress("check instances", size_t(count.integer(0)), display);
  db::Statement rows(db,
                     "SELECT i.id, i.object, i.sop_instance_uid, x.series_uid, s.study_uid FROM instances i "
                     "JOIN series x ON x.id = i.series JOIN studies s ON s.id = x.study ORDER BY i.id");
  while (rows.step()) {
    progress.advance();
    auto path = objects.path_of(rows.text(1));
    if (!std::filesystem::exists(path)) {
      ++report.instances_without_object;
      continue;
    }
    const std::string row = "instance:" + std::to_string(rows.integer(0)) + " (" + path.string() + ")";
    try {
      auto header = parse_instance_header(read_file(path), path);
      ++report.instances_checked;
      if (header.sop_instance_uid != rows.text(2) || header.series_uid != rows.text(3) ||
          header.study_uid != rows.text(4))
        report.disagreements.push_back(row + ": its DICOM UIDs differ from the journal's row");
    } catch (const Error& e) {
      report.disagreements.push_back(row + ": " + e.reason());
    }
  }
  progress.finish();
}

// DICOM objects that no journal entry named are indexed from their own headers (object_adoption.h);
// other unnamed files are listed.
void adopt_unindexed_objects(db::Connection& db, ObjectStore& objects, const IndexJournal& journal,
                             RebuildReport& report) {
  std::vector<std::filesystem::path> candidates;
  {
    db::Statement indexed(db, "SELECT 1 FROM objects WHERE sha256 = ?1");
    objects.for_each_file([&](ObjectStore::EntryKind kind, const std::string& sha, const std::filesystem::path& path) {
      if (kind != ObjectStore::EntryKind::Object) return;
      if (!indexed.reset().bind(1, sha).step()) candidates.push_back(path);
      indexed.reset();
    });
  }
  auto adoption = adopt_objects(db, objects, journal, std::move(candidates), {});
  report.dicom_adopted += adoption.adopted.size();
  for (auto& path : adoption.not_adopted) report.unexplained.push_back(std::move(path));
}

void count_rows(db::Connection& db, RebuildReport& report) {
  for (const auto& table : index_tables()) {
    db::Statement count(db, "SELECT COUNT(*) FROM " + table);
    count.step();
    report.rows[table] = count.integer(0);
  }
}

// The new index replaces the old one in one rename; the old one is kept, with its WAL.
void install(const std::filesystem::path& folder, const std::filesystem::path& rebuilt, bool was_intact,
             RebuildReport& report) {
  const auto index = index_file(folder);
  std::error_code error;
  if (std::filesystem::exists(index, error) || std::filesystem::exists(index.string() + "-wal", error)) {
    report.previous_index =
        folder / ("index.sqlite." + std::string(was_intact ? "replaced-" : "damaged-") + utc_stamp());
    for (const char* suffix : {"", "-wal"})
      if (std::filesystem::exists(index.string() + suffix, error))
        std::filesystem::rename(index.string() + suffix, report.previous_index.string() + suffix);
    std::filesystem::remove(index.string() + "-shm", error);  // derived from the WAL, rebuilt on open
  }
  std::filesystem::rename(rebuilt, index);
  sync_folder(folder);
}

// The index from the store: the journal replayed, instances checked against their objects,
// DICOM objects no entry names indexed from their headers, rows counted.
void rebuild_into(db::Connection& db, ObjectStore& objects, const IndexJournal& journal, ProgressDisplay display,
                  RebuildReport& report) {
  upgrade_schema(db, journal);
  auto outcome = replay_journal(db, journal);
  report.journal_entries = outcome.entries;
  report.journal_problems = std::move(outcome.problems);
  restore_named_objects(db, objects, report);
  check_instances(db, objects, display, report);
  adopt_unindexed_objects(db, objects, journal, report);
  count_rows(db, report);
}

// A server archive whose database was lost: rebuilt into a new, empty database (made by the
// administrator, as the address names it) from the shared object folder. A database that
// holds an index is never written over.
RebuildReport rebuild_on_server(const ArchiveLocation& location, const RebuildOptions& options) {
  if (!std::filesystem::is_directory(location.objects_folder()))
    throw Error(ErrorCode::kBadArchiveAddress, location.shown,
                "the shared object folder " + location.folder.string() + " does not exist");
  Archive::State state(location, open_index(location, sqlite::OpenKind::Existing));
  StoreLock lock(state, LockKind::Exclusive);
  if (state.db.schema_version() != 0)
    throw Error(ErrorCode::kConflict, location.shown,
                "this database holds an index; a server archive's index is rebuilt into a new, empty database "
                "(CREATE DATABASE, then point the address at it); the one here is left as it is");
  RebuildReport report;
  rebuild_into(state.db, state.objects, state.journal, options.progress, report);
  state.objects.make_durable();
  return report;
}

}  // namespace

RebuildReport Archive::rebuild_index(const std::filesystem::path& folder, const RebuildOptions& options) {
  initialise_dicom_toolkit();
  if (names_index_server(folder.string())) {
    auto report = rebuild_on_server(parse_archive_location(folder.string()), options);
    log::info("index rebuilt on the server from ", report.journal_entries, " journal entries and ",
              report.dicom_adopted, " DICOM objects no entry named");
    return report;
  }
  if (!std::filesystem::is_directory(objects_folder(folder)))
    throw Error(ErrorCode::kNotFound, folder.string(), "no object store (objects/) to rebuild an index from");
  StoreLock lock(folder, LockKind::Exclusive);
  IndexJournal journal(journal_folder(folder));
  const bool intact = index_is_intact(folder, journal);
  if (intact && !options.force)
    throw Error(ErrorCode::kConflict, index_file(folder).string(),
                "the index is intact; `archive rebuild-index --force` rebuilds it anyway (the current one is kept)");

  RebuildReport report;
  const auto rebuilt = folder / "index.sqlite.rebuilding";
  remove_index_files(rebuilt);
  {
    ObjectStore objects(objects_folder(folder));
    sqlite::Database db(rebuilt, sqlite::OpenKind::Create);
    db.use_archive_settings();
    rebuild_into(db, objects, journal, options.progress, report);
    require_intact_index(db);
    db.execute("PRAGMA journal_mode = DELETE");  // folds the WAL into the file before it moves
    objects.make_durable();
  }
  install(folder, rebuilt, intact, report);
  log::info("index rebuilt from ", report.journal_entries, " journal entries and ", report.dicom_adopted,
            " DICOM objects no entry named");
  return report;
}

}  // namespace maxillo
