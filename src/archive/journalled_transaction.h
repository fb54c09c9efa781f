#pragma once
// A write transaction on the archive index that records every row it writes in the index
// journal (index_journal.h). Use it for every change of the index: rows written through a
// plain db::Transaction would be lost by a rebuild.
//
//   JournalledTransaction transaction(db, journal, "artefact");
//   transaction.inserted("artefacts", db::inserted_id(insert).value());
//   transaction.commit();   // entry numbered, written durably, then COMMIT
//
// A transaction that captured no row commits without an entry.
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "archive/index_journal.h"
#include "archive/index_connection.h"

namespace maxillo {

// The whole row `table` holds where `where` (with ?1, ?2... bound to `keys`) is true, as JSON.
using SqlKey = std::variant<int64_t, std::string>;
// The current row of a query as JSON {column: value}.
Json row_json(const db::Statement& row);
Json row_as_json(db::Connection& db, std::string_view table, std::string_view where, const std::vector<SqlKey>& keys);

class JournalledTransaction {
 public:
  // kind: Immediate for every write; Exclusive for a schema migration (db::TransactionKind).
  JournalledTransaction(db::Connection& db, const IndexJournal& journal, std::string operation,
                        db::TransactionKind kind = db::TransactionKind::Immediate);

  // Records the row just inserted into a table whose key is `id`.
  void inserted(std::string_view table, int64_t id);
  // Records the row that an INSERT ... RETURNING * has just returned (`row` stands on it): no
  // second read of it, which on a server is a round trip per imported file.
  void inserted_row(std::string_view table, const db::Statement& row);
  // Records the row of `table` that `where` selects after a change (tables keyed otherwise,
  // updates).
  void written(std::string_view table, std::string_view where, const std::vector<SqlKey>& keys);
  // Records every row of `table` (the snapshot of an index that predates the journal).
  void all_rows_of(std::string_view table);
  bool empty() const { return entry_.rows.empty(); }
  // Numbers the entry, writes it durably, commits. Without rows: commits only.
  // The number comes from the index's counter row, updated last: that row's lock is the only
  // thing concurrent writers of a server index wait for, and only from here to COMMIT, so the
  // counter orders the commits as the journal numbers them (a server SEQUENCE would not: it
  // hands out numbers that commit in another order, or never, leaving gaps that read as a lost
  // commit, index_journal.h).
  void commit();

 private:
  db::Connection& db_;
  const IndexJournal& journal_;
  db::Transaction transaction_;
  JournalEntry entry_;
};

// The index's journal counter: entries 1..N are its committed history.
int64_t journal_sequence(db::Connection& db);

}  // namespace maxillo
