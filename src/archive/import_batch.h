#pragma once
// The second stage of an import, on the main thread: store the objects of a batch, make them
// durable (ObjectStore::make_durable), then commit all the batch's rows in one journalled transaction.
// Rows are therefore never committed before their files exist on stable storage.
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "archive/archive.h"
#include "archive/import_scan.h"
#include "archive/index_journal.h"
#include "archive/journalled_transaction.h"
#include "archive/object_store.h"
#include "archive/index_connection.h"

namespace maxillo {

class BatchWriter {
 public:
  // source_label: recorded as every instance's source instead of its file's path when not empty
  // (ImportOptions::source_label).
  BatchWriter(db::Connection& db, ObjectStore& objects, const IndexJournal& journal, std::string source_label = {});

  // Writes the file's object now (not yet durable) and queues its rows. A second file of the
  // batch with the same SOP Instance UID is not written: its outcome is returned at once
  // (AlreadyArchived for the same bytes, Conflict with `reason` otherwise); else Imported.
  ImportOutcome add(ScannedFile&& file, std::string& reason);
  size_t pending() const { return batch_.size(); }
  // Objects made durable, then one transaction for every queued file; each outcome goes into report.
  // options.on_problem and options.on_archived hear of each file once the transaction committed.
  void commit(ImportReport& report, const ImportOptions& options);

 private:
  std::string source_of(const ScannedFile& file) const;
  struct PatientState {
    int64_t id;
    int64_t default_case;
    std::string name, birth_date, sex;  // as archived
  };
  // What one attempt at a batch's transaction found, reported once it committed.
  struct BatchOutcome {
    ImportReport report;
    std::vector<ImportProblem> problems;  // conflicts
    std::vector<std::pair<std::filesystem::path, ImportOutcome>> archived;
    void record(const ScannedFile& file, ImportOutcome outcome, const std::string& reason);
  };
  // One attempt at the batch's transaction; the caller retries it whole.
  void insert_batch(const std::string& now, BatchOutcome& result);
  // After a rolled-back attempt: the ids it learnt may name rows that were never committed.
  void forget_known_rows();
  // SOP Instance UID -> object of the batch's instances the index already holds.
  std::map<std::string, std::string, std::less<>> archived_objects_of_batch();
  // Imported when `archived_object` (the instance's object in the index) is empty, else
  // AlreadyArchived for the same bytes or Conflict with `reason`.
  static ImportOutcome outcome_against(const ScannedFile& file, const std::string& archived_object,
                                       std::string& reason);
  // The same, asking the index now.
  ImportOutcome archived_outcome(const ScannedFile& file, std::string& reason);
  // A file whose rows are written in this transaction: its series and its patient's case.
  struct QueuedInstance {
    const ScannedFile* file;
    int64_t series;
    int64_t default_case;
  };
  QueuedInstance queue_rows(const ScannedFile& file, const std::string& now, ImportReport& report);
  // The queued files' object and instance rows, a few multi-row INSERTs for the whole batch
  // instead of two round trips per file; insert_instances returns the SOP Instance UIDs it
  // inserted (the others were archived meanwhile by another writer).
  void insert_queued(const std::vector<QueuedInstance>& queued, const std::string& now, BatchOutcome& result);
  void insert_objects(const std::vector<QueuedInstance>& queued);
  std::set<std::string, std::less<>> insert_instances(const std::vector<QueuedInstance>& queued,
                                                      const std::string& now);
  void bind_instance(db::Statement& insert, int at, const QueuedInstance& queued, const std::string& now);
  const PatientState& patient_of(const InstanceHeader& h, const std::string& now);
  void flag_identity(const PatientState& patient, const ScannedFile& file, const std::string& now,
                     ImportReport& report);
  int64_t study_of(const InstanceHeader& h, int64_t patient);
  int64_t series_of(const InstanceHeader& h, int64_t study, int64_t case_id);

  std::string source_label_;
  db::Connection& db_;
  ObjectStore& objects_;
  const IndexJournal& journal_;
  JournalledTransaction* transaction_ = nullptr;  // while commit() runs
  std::vector<ScannedFile> batch_;
  std::map<std::string, std::string, std::less<>> batch_objects_;  // SOP Instance UID -> sha256 in this batch
  db::Statement insert_patient_, patient_by_id_, insert_case_, case_of_patient_, insert_flag_;
  db::Statement insert_study_, study_by_uid_, insert_series_, series_by_uid_, attach_series_;
  db::Statement object_of_sop_, lock_case_;
  // Ids already known in this import; rows are never deleted, so they stay valid once
  // committed (forget_known_rows() drops them when their transaction rolled back).
  std::map<std::string, PatientState, std::less<>> patients_;
  std::map<std::string, int64_t, std::less<>> studies_, series_;
  std::set<std::tuple<int64_t, std::string, std::string>> flagged_;
};

}  // namespace maxillo
