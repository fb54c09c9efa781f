#pragma once
// Replaying the index journal (index_journal.h) into an index: how `archive rebuild-index`
// re-creates a lost index and how `verify` checks a live one against its history.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "archive/index_journal.h"
#include "archive/index_connection.h"

namespace maxillo {

// The tables of the index in foreign-key order (parents first); index_state is not among them.
const std::vector<std::string>& index_tables();

// Writes journal rows into an index of the current schema: one upsert per row, in the entry's
// order. Table and column names are checked against the schema, so a damaged or hostile entry
// can fail (Error kIndexDamaged naming the entry) but never run other SQL.
class JournalReplayer {
 public:
  explicit JournalReplayer(db::Connection& db);
  ~JournalReplayer();
  JournalReplayer(const JournalReplayer&) = delete;
  JournalReplayer& operator=(const JournalReplayer&) = delete;
  void apply(const JournalEntry& entry, const std::filesystem::path& source);

 private:
  struct Statements;
  db::Connection& db_;
  std::map<std::string, std::vector<std::string>> columns_;  // per table, from the schema
  Statements* statements_;
};

struct ReplayOutcome {
  size_t entries = 0;                 // entries applied
  int64_t last_sequence = 0;          // the highest applied (0 when none)
  std::vector<std::string> problems;  // "entry 12: missing", "entry 13: <reason>"
};

// Applies entries 1..up_to (every entry present when up_to is empty) to `db` in one
// transaction, then sets its journal counter to the last entry applied. A missing or unreadable
// entry is a problem that is reported and skipped, never a reason to stop.
ReplayOutcome replay_journal(db::Connection& db, const IndexJournal& journal, std::optional<int64_t> up_to = {});

}  // namespace maxillo
