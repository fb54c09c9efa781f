#pragma once
// The index journal: an append-only record, kept beside the objects, of every row the archive
// index gained or changed. With it the index can be lost and rebuilt exactly (ids included):
// the objects hold the data, the journal holds what the index said about them (cases, roles,
// artefacts and their provenance, import paths and times).
//
//   OBJECTS/journal/00000000/000000000001.json   entry 1 (a folder per 10,000 entries)
//
// An entry is written (temp file, fsync, rename, fsync of the folder) inside the index
// transaction it describes, after BEGIN IMMEDIATE and before COMMIT, so:
// - every committed transaction has its entry on stable storage;
// - entries are numbered in commit order by a counter kept in the index (index_state), which
//   the write lock serialises;
// - a transaction that dies between writing its entry and committing leaves an entry numbered
//   one past the index's counter; the next transaction reuses that number and its rename
//   replaces the stale entry. Hence entries 1..N (N = the index's counter) are exactly the
//   committed history, and an entry N+2 proves the index is behind its journal.
//
// Each row is the whole row after the change, so replaying entries in order (an upsert per
// row) reproduces the index table for table. Rows are JSON objects {column: value}; values are
// integers, reals, strings or null, as SQLite stored them.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/json.h"

namespace maxillo {

struct JournalRow {
  std::string table;
  Json values;  // {column: value}, the whole row
};

struct JournalEntry {
  int64_t sequence = 0;
  std::string at;                // UTC ISO 8601, when the transaction ran
  std::string operation;         // "import", "artefact", "object", "case", "role", "snapshot", ...
  std::string program_version;   // of the program that wrote it
  std::vector<JournalRow> rows;  // in the order they were written (foreign keys first)
};

std::string journal_entry_text(const JournalEntry& entry);
// Throws Error(kIndexDamaged) naming `path` when the text is not a journal entry.
JournalEntry parse_journal_entry(std::string_view text, const std::filesystem::path& path);

class IndexJournal {
 public:
  // `folder` is OBJECTS/journal; it is created on the first write.
  explicit IndexJournal(std::filesystem::path folder);

  std::filesystem::path path_of(int64_t sequence) const;
  bool has(int64_t sequence) const;
  // Durable before it returns (see above). Replaces a stale entry of the same number.
  void write(const JournalEntry& entry) const;
  // Throws Error(kIndexDamaged) when the entry is unreadable or not an entry.
  JournalEntry read(int64_t sequence) const;
  // Every entry number present, ascending.
  std::vector<int64_t> sequences() const;
  // True when the folder holds at least one entry (cheap: stops at the first).
  bool empty() const;

  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_;
};

}  // namespace maxillo
