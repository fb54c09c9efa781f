#pragma once
// Objects in the store that no index row names, indexed from their own DICOM headers through
// the import's own writer (journalled like any import). Two kinds of work need it:
// `archive rebuild-index`, for objects older than the journal or named by a lost entry, and
// `verify --repair`, for what an interrupted import left: an object written and synced whose
// rows were never committed (kill -9, a full disk). Adopting such an object is what importing
// its file again would do; it loses nothing and invents nothing.
#include <filesystem>
#include <string>
#include <vector>

#include "archive/index_connection.h"
#include "archive/index_journal.h"
#include "archive/object_store.h"

namespace maxillo {

struct AdoptionResult {
  std::vector<std::filesystem::path> adopted;
  std::vector<std::filesystem::path> not_adopted;  // not DICOM instances, damaged, or refused by the import
};

// `objects` are paths in the store (named by their SHA-256). `source_label` is recorded as the
// adopted instances' source. Commits in batches of 500.
AdoptionResult adopt_objects(db::Connection& db, ObjectStore& store, const IndexJournal& journal,
                             std::vector<std::filesystem::path> objects, const std::string& source_label);

}  // namespace maxillo
