// Cases made without an import: a patient row (by Patient ID) and a labelled case.
#include "archive/archive_sql.h"
#include "archive/archive_state.h"
#include "archive/journalled_transaction.h"

namespace maxillo {

int64_t Archive::ensure_case(std::string_view patient_id, std::string_view label) {
  if (patient_id.empty()) throw Error(ErrorCode::kBadValue, "case", "empty Patient ID");
  if (label.empty()) throw Error(ErrorCode::kBadValue, std::string(patient_id), "empty case label");
  const std::string now = utc_now();
  StoreLock lock(*state_, LockKind::Shared);  // verify and rebuild see no half-done change
  JournalledTransaction transaction(state_->db, state_->journal, "case");
  db::Statement insert_patient(state_->db, sql::kInsertPatient);
  insert_patient.bind(1, patient_id).bind(2, "").bind(3, "").bind(4, "").bind(5, now);
  if (auto id = db::inserted_id(insert_patient)) transaction.inserted("patients", *id);
  db::Statement patient(state_->db, sql::kPatientByPatientId);
  patient.bind(1, patient_id);
  patient.step();
  const int64_t patient_row = patient.integer(0);
  db::Statement insert_case(state_->db, sql::kInsertLabelledCase);
  insert_case.bind(1, patient_row).bind(2, label).bind(3, now);
  if (auto id = db::inserted_id(insert_case)) transaction.inserted("cases", *id);
  transaction.commit();
  return case_of_patient(patient_row, label)->id;
}

}  // namespace maxillo
