#pragma once
// Checks made each time an archive is opened, so that no command works on an index that has
// been lost, damaged or rolled back while the object store still holds the data. A lost index
// re-created empty would make every object look like an orphan; these checks refuse instead
// (Error kIndexDamaged, exit 46) and say how to recover: `maxillo archive rebuild-index`.
#include <filesystem>

#include "archive/index_journal.h"
#include "archive/index_connection.h"

namespace maxillo {

enum class IndexPresence { Present, Fresh };

// Present: index.sqlite exists and is not empty. Fresh: no index and nothing stored yet (a
// new archive). Throws Error(kIndexDamaged) when the index is missing or empty while the
// object store holds objects, journal entries or quarantined files.
IndexPresence check_index_presence(const std::filesystem::path& archive_folder);

// PRAGMA quick_check (about 0.2 s for a 160 MB index of 300,000 instances). Throws
// Error(kIndexDamaged) with SQLite's first complaint.
void require_intact_index(db::Connection& db);

// Throws Error(kIndexDamaged) when the journal holds a committed entry past the index's counter
// (see index_journal.h): the index was restored from an older copy or lost its last commits,
// by however many.
void require_index_not_behind_journal(db::Connection& db, const IndexJournal& journal);

// An archive being filled by `archive migrate` is marked until the migration has verified it, so
// that a migration killed half-way is not taken for an archive that holds less (issue 29).
void mark_migration_started(const std::filesystem::path& objects_folder, const std::string& source);
void mark_migration_finished(const std::filesystem::path& objects_folder);
// Throws Error(kConflict) naming the source and how to finish, when the mark is there.
void require_no_unfinished_migration(const std::filesystem::path& objects_folder, const std::string& shown);

// True when any regular file exists below `folder` (stops at the first one found).
bool holds_any_file(const std::filesystem::path& folder);

}  // namespace maxillo
