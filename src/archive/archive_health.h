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

// Throws Error(kIndexDamaged) when the journal holds entries the index never committed beyond
// the one an interrupted transaction may leave (see index_journal.h): the index was restored
// from an older copy or lost its last commits.
void require_index_not_behind_journal(db::Connection& db, const IndexJournal& journal);

// True when any regular file exists below `folder` (stops at the first one found).
bool holds_any_file(const std::filesystem::path& folder);

}  // namespace maxillo
