#include "archive/import_batch.h"

#include <algorithm>

#include "archive/archive_sql.h"
#include "archive/archive_state.h"

namespace maxillo {
namespace {

std::string conflict_reason(const std::string& sop_instance_uid, const std::string& archived_sha256) {
  return "SOP Instance UID " + sop_instance_uid + " is archived with other content (object " +
         archived_sha256.substr(0, 12) + "...); the archived file is kept";
}

}  // namespace

BatchWriter::BatchWriter(db::Connection& db, ObjectStore& objects, const IndexJournal& journal,
                         std::string source_label)
    : source_label_(std::move(source_label)),
      db_(db),
      objects_(objects),
      journal_(journal),
      insert_patient_(db, sql::kInsertPatient),
      patient_by_id_(db, sql::kPatientByPatientId),
      insert_case_(db, sql::kInsertDefaultCase),
      case_of_patient_(db, sql::kDefaultCaseOfPatient),
      insert_flag_(db, sql::kInsertIdentityFlag),
      insert_study_(db, sql::kInsertStudy),
      study_by_uid_(db, sql::kStudyIdByUid),
      insert_series_(db, sql::kInsertSeries),
      series_by_uid_(db, sql::kSeriesIdByUid),
      attach_series_(db, sql::kAttachSeriesToCase),
      object_of_sop_(db, sql::kObjectOfSopInstance),
      lock_case_(db, sql::kLockCase) {}

std::string BatchWriter::source_of(const ScannedFile& file) const {
  return source_label_.empty() ? std::filesystem::absolute(file.path).string() : source_label_;
}

ImportOutcome BatchWriter::add(ScannedFile&& file, std::string& reason) {
  auto [earlier, first] = batch_objects_.emplace(file.header.sop_instance_uid, file.sha256);
  if (!first) {
    if (earlier->second == file.sha256) return ImportOutcome::AlreadyArchived;
    reason = conflict_reason(file.header.sop_instance_uid, earlier->second);
    return ImportOutcome::Conflict;  // its bytes are never stored: nothing would name them
  }
  objects_.put(file.sha256, file.bytes);
  file.bytes = {};  // the file is on disk now; keep batches small in memory
  batch_.push_back(std::move(file));
  return ImportOutcome::Imported;
}

void BatchWriter::commit(ImportReport& report, const ImportOptions& options) {
  if (batch_.empty()) return;
  objects_.make_durable();
  const std::string now = utc_now();
  BatchOutcome result;
  // Writers of a server index run side by side and may deadlock on rows both write (the same
  // patient, instance or object in another order): the server then rolls one back, and the
  // whole batch runs again from scratch.
  db::retry_transaction([&] {
    result = {};
    try {
      insert_batch(now, result);
    } catch (const Error&) {
      forget_known_rows();  // rows this transaction made are gone with it
      throw;
    }
  });
  // Counted only once committed: a failed commit throws and counts nothing.
  ImportReport& outcome = result.report;
  report.imported += outcome.imported;
  report.already_archived += outcome.already_archived;
  report.identity_flags += outcome.identity_flags;
  report.cases_with_new_images.merge(outcome.cases_with_new_images);
  if (options.on_archived)
    for (const auto& [path, archived] : result.archived) options.on_archived(path, archived);
  for (auto& problem : result.problems) {
    ++report.conflicts;
    if (options.on_problem) options.on_problem(problem);
    report.problems.push_back(std::move(problem));
  }
  batch_.clear();
  batch_objects_.clear();
}

void BatchWriter::BatchOutcome::record(const ScannedFile& file, ImportOutcome outcome, const std::string& reason) {
  if (outcome == ImportOutcome::Conflict) {
    problems.push_back({file.path, ImportOutcome::Conflict, ErrorCode::kConflict, reason});
    return;
  }
  ++(outcome == ImportOutcome::Imported ? report.imported : report.already_archived);
  archived.emplace_back(file.path, outcome);
}

void BatchWriter::insert_batch(const std::string& now, BatchOutcome& result) {
  JournalledTransaction transaction(db_, journal_, "import");
  transaction_ = &transaction;
  struct Forget {
    JournalledTransaction*& current;
    ~Forget() { current = nullptr; }
  } forget{transaction_};
  const auto archived_before = archived_objects_of_batch();
  std::vector<QueuedInstance> queued;
  for (const auto& file : batch_) {
    std::string reason;
    const auto found = archived_before.find(file.header.sop_instance_uid);
    const std::string no_object;
    const std::string& archived_object = found == archived_before.end() ? no_object : found->second;
    // Decided before any row is written, so a rejected file raises no identity flag and makes
    // no patient (unless another writer of a server index wins its instance row, below).
    if (const auto outcome = outcome_against(file, archived_object, reason); outcome != ImportOutcome::Imported) {
      result.record(file, outcome, reason);
      continue;
    }
    queued.push_back(queue_rows(file, now, result.report));
  }
  insert_queued(queued, now, result);
  transaction.commit();
}

void BatchWriter::insert_queued(const std::vector<QueuedInstance>& queued, const std::string& now,
                                BatchOutcome& result) {
  // Rows in key order: writers inserting overlapping batches then lock them in the same order
  // and wait for each other instead of deadlocking. Outcomes stay in the files' order.
  std::vector<QueuedInstance> in_key_order = queued;
  std::sort(in_key_order.begin(), in_key_order.end(),
            [](const QueuedInstance& a, const QueuedInstance& b) { return a.file->sha256 < b.file->sha256; });
  insert_objects(in_key_order);
  std::sort(in_key_order.begin(), in_key_order.end(), [](const QueuedInstance& a, const QueuedInstance& b) {
    return a.file->header.sop_instance_uid < b.file->header.sop_instance_uid;
  });
  const std::set<std::string, std::less<>> inserted = insert_instances(in_key_order, now);
  for (const QueuedInstance& row : queued) {
    std::string reason;
    // No row: a concurrent writer of a server index inserted this SOP Instance UID after
    // archived_objects_of_batch() looked, and committed (the insert waited for it). Theirs is
    // the row; ours is the same file again or a conflict. (The object row made for a
    // conflicting file's bytes stays, naming a stored file like any object.)
    if (!inserted.contains(row.file->header.sop_instance_uid)) {
      result.record(*row.file, archived_outcome(*row.file, reason), reason);
      continue;
    }
    result.report.cases_with_new_images.insert(row.default_case);
    result.record(*row.file, ImportOutcome::Imported, reason);
  }
}

// Rows per multi-row INSERT: a batch of 500 in two round trips per table, parameters well
// under either engine's limit.
constexpr size_t kRowsPerInsert = 256;

void BatchWriter::insert_objects(const std::vector<QueuedInstance>& queued) {
  for (size_t first = 0; first < queued.size(); first += kRowsPerInsert) {
    const size_t rows = std::min(kRowsPerInsert, queued.size() - first);
    db::Statement insert(db_, std::string(sql::kInsertObjectsHead) +
                                  db::value_rows(int(rows), sql::kObjectColumnCount) + sql::kInsertObjectsTail);
    for (size_t n = 0; n < rows; ++n) {
      const ScannedFile& file = *queued[first + n].file;
      const int at = int(n) * sql::kObjectColumnCount;
      insert.bind(at + 1, file.sha256).bind(at + 2, int64_t(file.size));
    }
    // No row for bytes already stored (another file of these bytes, another writer).
    while (insert.step()) transaction_->inserted_row("objects", insert);
  }
}

std::set<std::string, std::less<>> BatchWriter::insert_instances(const std::vector<QueuedInstance>& queued,
                                                                 const std::string& now) {
  std::set<std::string, std::less<>> inserted;
  for (size_t first = 0; first < queued.size(); first += kRowsPerInsert) {
    const size_t rows = std::min(kRowsPerInsert, queued.size() - first);
    db::Statement insert(db_, std::string(sql::kInsertInstancesHead) +
                                  db::value_rows(int(rows), sql::kInstanceColumnCount) + sql::kInsertInstancesTail);
    for (size_t n = 0; n < rows; ++n) bind_instance(insert, int(n) * sql::kInstanceColumnCount, queued[first + n], now);
    int uid_column = -1;
    while (insert.step()) {
      if (uid_column < 0)
        while (insert.column_name(++uid_column) != "sop_instance_uid") {}
      inserted.insert(insert.text(uid_column));
      transaction_->inserted_row("instances", insert);
    }
  }
  return inserted;
}

void BatchWriter::bind_instance(db::Statement& insert, int at, const QueuedInstance& queued, const std::string& now) {
  const ScannedFile& file = *queued.file;
  const InstanceHeader& h = file.header;
  insert.bind(at + 1, queued.series).bind(at + 2, h.sop_instance_uid).bind(at + 3, h.sop_class_uid);
  insert.bind(at + 4, h.instance_number).bind(at + 5, h.image_position).bind(at + 6, h.image_orientation);
  insert.bind(at + 7, h.transfer_syntax_uid).bind(at + 8, file.sha256).bind(at + 9, int64_t(file.size));
  insert.bind(at + 10, source_of(file)).bind(at + 11, now);
}

void BatchWriter::forget_known_rows() {
  patients_.clear();
  studies_.clear();
  series_.clear();
  flagged_.clear();
}

// Another process may have archived these SOP Instance UIDs since the scanner looked: asked
// for the whole batch at once, at the start of its transaction.
std::map<std::string, std::string, std::less<>> BatchWriter::archived_objects_of_batch() {
  std::vector<std::string> uids;
  for (const auto& file : batch_) uids.push_back(file.header.sop_instance_uid);
  std::map<std::string, std::string, std::less<>> objects;
  db::for_each_row_with_keys(db_, sql::kObjectsOfSopInstancesIn, ")", std::move(uids),
                             [&](const db::Statement& row) { objects.emplace(row.text(0), row.text(1)); });
  return objects;
}

ImportOutcome BatchWriter::outcome_against(const ScannedFile& file, const std::string& archived_object,
                                           std::string& reason) {
  if (archived_object.empty()) return ImportOutcome::Imported;
  if (archived_object == file.sha256) return ImportOutcome::AlreadyArchived;
  reason = conflict_reason(file.header.sop_instance_uid, archived_object);
  return ImportOutcome::Conflict;
}

ImportOutcome BatchWriter::archived_outcome(const ScannedFile& file, std::string& reason) {
  std::string archived;
  if (object_of_sop_.reset().bind(1, file.header.sop_instance_uid).step()) archived = object_of_sop_.text(0);
  object_of_sop_.reset();
  return outcome_against(file, archived, reason);
}

// The patient, case, study and series rows of a file about to be archived; its object and
// instance rows are inserted with the batch's (insert_objects, insert_instances).
BatchWriter::QueuedInstance BatchWriter::queue_rows(const ScannedFile& file, const std::string& now,
                                                    ImportReport& report) {
  const InstanceHeader& h = file.header;
  const PatientState& patient = patient_of(h, now);
  flag_identity(patient, file, now, report);
  const int64_t series = series_of(h, study_of(h, patient.id), patient.default_case);
  return {&file, series, patient.default_case};
}

const BatchWriter::PatientState& BatchWriter::patient_of(const InstanceHeader& h, const std::string& now) {
  if (auto found = patients_.find(h.patient_id); found != patients_.end()) return found->second;
  insert_patient_.reset()
      .bind(1, h.patient_id)
      .bind(2, h.patient_name)
      .bind(3, h.birth_date)
      .bind(4, h.sex)
      .bind(5, now);
  if (auto id = db::inserted_id(insert_patient_)) transaction_->inserted("patients", *id);
  PatientState state{};
  patient_by_id_.reset().bind(1, h.patient_id).step();
  state.id = patient_by_id_.integer(0);
  state.name = patient_by_id_.text(1);
  state.birth_date = patient_by_id_.text(2);
  state.sex = patient_by_id_.text(3);
  patient_by_id_.reset();
  if (auto id = db::inserted_id(insert_case_.reset().bind(1, state.id).bind(2, now)))
    transaction_->inserted("cases", *id);
  state.default_case = db::single_integer(case_of_patient_.reset().bind(1, state.id));
  return patients_.emplace(h.patient_id, std::move(state)).first->second;
}

void BatchWriter::flag_identity(const PatientState& patient, const ScannedFile& file, const std::string& now,
                                ImportReport& report) {
  const InstanceHeader& h = file.header;
  const std::pair<const char*, std::pair<const std::string*, const std::string*>> attributes[] = {
      {"name", {&patient.name, &h.patient_name}},
      {"birth_date", {&patient.birth_date, &h.birth_date}},
      {"sex", {&patient.sex, &h.sex}}};
  for (const auto& [attribute, values] : attributes) {
    const auto& [archived, arrived] = values;
    if (*archived == *arrived) continue;
    if (!flagged_.emplace(patient.id, attribute, *arrived).second) continue;
    insert_flag_.reset().bind(1, patient.id).bind(2, attribute).bind(3, *archived).bind(4, *arrived);
    insert_flag_.bind(5, source_of(file)).bind(6, h.sop_instance_uid).bind(7, now);
    auto id = db::inserted_id(insert_flag_);
    if (!id) continue;
    transaction_->inserted("identity_flags", *id);
    ++report.identity_flags;
  }
}

int64_t BatchWriter::study_of(const InstanceHeader& h, int64_t patient) {
  if (auto found = studies_.find(h.study_uid); found != studies_.end()) return found->second;
  insert_study_.reset().bind(1, patient).bind(2, h.study_uid).bind(3, h.study_date).bind(4, h.study_time);
  insert_study_.bind(5, h.study_description).bind(6, h.accession_number);
  if (auto inserted = db::inserted_id(insert_study_)) transaction_->inserted("studies", *inserted);
  int64_t id = db::single_integer(study_by_uid_.reset().bind(1, h.study_uid));
  return studies_.emplace(h.study_uid, id).first->second;
}

int64_t BatchWriter::series_of(const InstanceHeader& h, int64_t study, int64_t case_id) {
  if (auto found = series_.find(h.series_uid); found != series_.end()) return found->second;
  auto& s = insert_series_.reset();
  s.bind(1, study).bind(2, h.series_uid).bind(3, h.modality).bind(4, h.series_description);
  s.bind(5, h.series_number).bind(6, h.rows).bind(7, h.columns);
  s.bind(8, h.pixel_spacing_row).bind(9, h.pixel_spacing_column).bind(10, h.slice_thickness);
  if (auto inserted = db::inserted_id(s)) transaction_->inserted("series", *inserted);
  int64_t id = db::single_integer(series_by_uid_.reset().bind(1, h.series_uid));
  // Which CT series is a case's first decides its role: concurrent writers attaching CT series
  // to one case take turns on the case's row, so the second sees the first's 'preop'.
  if (h.modality == "CT") lock_case_.reset().bind(1, case_id).run();
  if (attach_series_.reset().bind(1, case_id).bind(2, id).bind(3, h.modality).run() == 1)
    transaction_->written("case_series", "case_id = ?1 AND series = ?2", {case_id, id});
  return series_.emplace(h.series_uid, id).first->second;
}

}  // namespace maxillo
