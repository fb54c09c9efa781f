#include "archive/import_batch.h"

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
      insert_object_(db, sql::kInsertObject),
      insert_instance_(db, sql::kInsertInstance),
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
  ImportReport outcome;
  std::vector<ImportProblem> problems;
  std::vector<std::pair<std::filesystem::path, ImportOutcome>> archived;
  // Writers of a server index run side by side and may deadlock on rows both write (the same
  // patient, instance or object in another order): the server then rolls one back, and the
  // whole batch runs again from scratch.
  db::retry_transaction([&] {
    outcome = {};
    problems.clear();
    archived.clear();
    try {
      insert_batch(now, outcome, problems, archived);
    } catch (const Error&) {
      forget_known_rows();  // rows this transaction made are gone with it
      throw;
    }
  });
  // Counted only once committed: a failed commit throws and counts nothing.
  report.imported += outcome.imported;
  report.already_archived += outcome.already_archived;
  report.identity_flags += outcome.identity_flags;
  report.cases_with_new_images.merge(outcome.cases_with_new_images);
  if (options.on_archived)
    for (const auto& [path, result] : archived) options.on_archived(path, result);
  for (auto& problem : problems) {
    ++report.conflicts;
    if (options.on_problem) options.on_problem(problem);
    report.problems.push_back(std::move(problem));
  }
  batch_.clear();
  batch_objects_.clear();
}

void BatchWriter::insert_batch(const std::string& now, ImportReport& outcome, std::vector<ImportProblem>& problems,
                               std::vector<std::pair<std::filesystem::path, ImportOutcome>>& archived) {
  JournalledTransaction transaction(db_, journal_, "import");
  transaction_ = &transaction;
  struct Forget {
    JournalledTransaction*& current;
    ~Forget() { current = nullptr; }
  } forget{transaction_};
  const auto archived_before = archived_objects_of_batch();
  for (const auto& file : batch_) {
    std::string reason;
    const auto found = archived_before.find(file.header.sop_instance_uid);
    const std::string no_object;
    const std::string& archived_object = found == archived_before.end() ? no_object : found->second;
    switch (const ImportOutcome result = insert(file, archived_object, now, outcome, reason)) {
      case ImportOutcome::Imported:
        ++outcome.imported;
        archived.emplace_back(file.path, result);
        break;
      case ImportOutcome::AlreadyArchived:
        ++outcome.already_archived;
        archived.emplace_back(file.path, result);
        break;
      default: problems.push_back({file.path, ImportOutcome::Conflict, ErrorCode::kConflict, reason}); break;
    }
  }
  transaction.commit();
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

// Decided before any row is written, so a rejected file raises no identity flag and makes no
// patient (unless another writer of a server index wins the race for its instance row, below).
ImportOutcome BatchWriter::insert(const ScannedFile& file, const std::string& archived_object, const std::string& now,
                                  ImportReport& report, std::string& reason) {
  if (auto outcome = outcome_against(file, archived_object, reason); outcome != ImportOutcome::Imported) return outcome;
  const InstanceHeader& h = file.header;
  const PatientState& patient = patient_of(h, now);
  flag_identity(patient, file, now, report);
  int64_t series = series_of(h, study_of(h, patient.id), patient.default_case);
  auto& object = insert_object_.reset().bind(1, file.sha256).bind(2, int64_t(file.size));
  if (object.step()) transaction_->inserted_row("objects", object);  // none: another file of these bytes
  object.reset();
  auto& s = insert_instance_.reset();
  s.bind(1, series).bind(2, h.sop_instance_uid).bind(3, h.sop_class_uid);
  s.bind(4, h.instance_number);
  s.bind(5, h.image_position).bind(6, h.image_orientation).bind(7, h.transfer_syntax_uid).bind(8, file.sha256);
  s.bind(9, int64_t(file.size)).bind(10, source_of(file)).bind(11, now);
  const bool inserted = s.step();
  if (inserted) transaction_->inserted_row("instances", s);
  s.reset();
  // No row: a concurrent writer of a server index inserted this SOP Instance UID after
  // archived_objects_of_batch() looked, and committed (the insert waited for it). Theirs is the row;
  // ours is the same file again or a conflict. (The object row made above for a conflicting
  // file's bytes stays, naming a stored file like any object.)
  if (!inserted) return archived_outcome(file, reason);
  report.cases_with_new_images.insert(patient.default_case);
  return ImportOutcome::Imported;
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
