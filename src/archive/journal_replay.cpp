#include "archive/journal_replay.h"

#include <memory>

#include "core/error.h"
#include "core/utf8.h"

namespace maxillo {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& source, const std::string& reason) {
  throw Error(ErrorCode::kIndexDamaged, source.string(), "journal entry cannot be replayed: " + reason);
}

void bind_value(db::Statement& statement, int index, const Json& value, const std::filesystem::path& source) {
  if (value.is_null())
    statement.bind_null(index);
  else if (value.is_number_integer())
    statement.bind(index, value.get<int64_t>());
  else if (value.is_number())
    statement.bind(index, value.get<double>());
  else if (value.is_string())
    statement.bind(index, bytes_from_utf8(value.get<std::string>()));
  else
    refuse(source, "a value is neither a number, a string nor null");
}

// The key of each index table (db/001_initial.sql).
std::string primary_key(const std::string& table) {
  if (table == "objects") return "sha256";
  if (table == "case_series") return "case_id, series";
  return "id";
}

// Rows written with their own ids leave an identity (PostgreSQL's) behind them: it moves past
// the highest id, so the next insert does not collide with a replayed row.
void advance_identities(db::Connection& db) {
  for (const auto& table : index_tables())
    if (primary_key(table) == "id") db.advance_identity(table);
}

}  // namespace

const std::vector<std::string>& index_tables() {
  static const std::vector<std::string> tables = {"patients",       "studies", "series",      "objects",  "instances",
                                                  "identity_flags", "cases",   "case_series", "artefacts"};
  return tables;
}

struct JournalReplayer::Statements {
  std::map<std::string, std::unique_ptr<db::Statement>> by_table;
};

JournalReplayer::JournalReplayer(db::Connection& db) : db_(db), statements_(new Statements) {
  for (const auto& table : index_tables()) columns_[table] = db.table_columns(table);
}

JournalReplayer::~JournalReplayer() { delete statements_; }

void JournalReplayer::apply(const JournalEntry& entry, const std::filesystem::path& source) {
  for (const auto& row : entry.rows) {
    auto known = columns_.find(row.table);
    if (known == columns_.end()) refuse(source, "unknown table \"" + row.table + "\"");
    const auto& columns = known->second;
    if (row.values.size() != columns.size()) refuse(source, "a row of " + row.table + " has the wrong columns");
    auto& statement = statements_->by_table[row.table];
    if (!statement) {
      // Every row is the whole row, so the column list is the schema's, in the schema's order.
      // An upsert on the table's key: a later entry's row replaces an earlier one.
      std::string names, places, updates;
      for (size_t c = 0; c < columns.size(); ++c) {
        names += (c ? ", " : "") + columns[c];
        places += (c ? ", ?" : "?") + std::to_string(c + 1);
        updates += (c ? ", " : "") + columns[c] + " = excluded." + columns[c];
      }
      statement = std::make_unique<db::Statement>(db_, "INSERT INTO " + row.table + " (" + names + ") VALUES (" +
                                                           places + ") ON CONFLICT (" + primary_key(row.table) +
                                                           ") DO UPDATE SET " + updates);
    }
    statement->reset();
    for (size_t c = 0; c < columns.size(); ++c) {
      auto value = row.values.find(columns[c]);
      if (value == row.values.end()) refuse(source, "a row of " + row.table + " lacks column " + columns[c]);
      bind_value(*statement, int(c + 1), *value, source);
    }
    statement->run();
  }
}

ReplayOutcome replay_journal(db::Connection& db, const IndexJournal& journal, std::optional<int64_t> up_to) {
  ReplayOutcome outcome;
  auto present = journal.sequences();
  const int64_t last = up_to.value_or(present.empty() ? 0 : present.back());
  db::Transaction transaction(db);
  JournalReplayer replayer(db);
  for (int64_t sequence = 1; sequence <= last; ++sequence) {
    if (!journal.has(sequence)) {
      outcome.problems.push_back("entry " + std::to_string(sequence) + ": missing (" +
                                 journal.path_of(sequence).string() + ")");
      continue;
    }
    // An entry applies whole or not at all.
    db.execute("SAVEPOINT entry");
    try {
      replayer.apply(journal.read(sequence), journal.path_of(sequence));
      db.execute("RELEASE entry");
      ++outcome.entries;
      outcome.last_sequence = sequence;
    } catch (const Error& e) {
      db.execute("ROLLBACK TO entry; RELEASE entry");
      outcome.problems.push_back("entry " + std::to_string(sequence) + ": " + e.reason());
    }
  }
  db::Statement counter(db, "UPDATE index_state SET journal_sequence = ?1 WHERE id = 1");
  counter.bind(1, last).run();
  advance_identities(db);
  transaction.commit();
  return outcome;
}

}  // namespace maxillo
