#pragma once
// The index journal: an append-only record, kept beside the objects, of every row the archive
// index gained or changed. With it the index can be lost and rebuilt exactly (ids included):
// the objects hold the data, the journal holds what the index said about them (cases, roles,
// artefacts and their provenance, import paths and times).
//
//   OBJECTS/journal/00000000/000000000001.json   entry 1 (a folder per 10,000 entries)
//
// An entry is written in two steps around the index transaction it describes:
// - after the counter below is taken and before COMMIT, durably as a *pending* entry
//   (NNN.pending: temp file, fsync, rename, fsync of the folder);
// - after COMMIT, marked committed by renaming it to NNN.json.
// So:
// - every committed transaction has its entry on stable storage;
// - entries are numbered in commit order by a counter kept in the index (index_state), taken
//   last in each transaction: the counter row stays locked until its writer's COMMIT (SQLite:
//   the file's write lock), so the next writer's number waits for it;
// - a committed entry (.json) is never written over: entries 1..N (N = the index's counter) are
//   the committed history, and a committed entry N+1 proves the index is behind its journal
//   (restored from an older copy, or lost its last commit);
// - a pending entry numbered N+1 is a transaction that died before its commit: the next writer
//   sets it aside under journal/aborted/ (kept, never deleted) and writes its own;
// - a pending entry numbered N or below is a transaction that died between COMMIT and the mark:
//   the index proves it committed, so the next writer or the next open marks it (`settle`).
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

  // A committed entry's file (NNN.json) and a pending one's (NNN.pending).
  std::filesystem::path path_of(int64_t sequence) const;
  std::filesystem::path pending_path_of(int64_t sequence) const;
  // Whether entry `sequence` is committed.
  bool has(int64_t sequence) const;
  bool has_pending(int64_t sequence) const;

  // Holding the index's counter (journalled_transaction.h), before COMMIT; durable before it returns. Never replaces an
  // entry: a committed entry of this number means the index is behind its journal (throws
  // Error(kIndexDamaged)); a pending one was left by a transaction that died before its commit
  // and is moved to journal/aborted/ first.
  void write_pending(const JournalEntry& entry) const;
  // After COMMIT: the pending entry becomes committed. Another process may have done it
  // already (`settle`), which is fine.
  void mark_committed(int64_t sequence) const;
  // Marks entry `committed_up_to` committed when it is still pending (its writer died between
  // COMMIT and the mark; the index's counter proves the commit). False when it could not be
  // marked (a read-only archive): readers then do without it.
  bool settle(int64_t committed_up_to) const;
  // A committed entry copied from another journal (archive migrate): written when absent,
  // left when the same entry is there, refused (Error(kConflict)) when another one is.
  void write_committed(const JournalEntry& entry) const;

  // Throws Error(kIndexDamaged) when the entry is unreadable or not an entry.
  JournalEntry read(int64_t sequence) const;
  // Every committed entry number present, ascending.
  std::vector<int64_t> sequences() const;
  // True when the folder holds at least one entry (cheap: stops at the first).
  bool empty() const;

  const std::filesystem::path& folder() const { return folder_; }

 private:
  // A pending entry of a transaction that never committed, moved under journal/aborted/.
  void set_aside_aborted(int64_t sequence) const;

  std::filesystem::path folder_;
};

}  // namespace maxillo
