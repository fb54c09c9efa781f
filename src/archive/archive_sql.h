#pragma once
// Every SQL statement the archive runs, in one place (the schema itself is db/*.sql), written
// once in the SQL that SQLite and PostgreSQL both accept (index_connection.h). Parameters are
// positional (?1, ?2...) and documented beside each statement. An insert that makes a row
// returns its id (RETURNING id): no row back means the row was already there.

namespace maxillo::sql {

// --- import ---
inline constexpr const char* kInstanceWithObject = "SELECT 1 FROM instances WHERE object = ?1 LIMIT 1";
inline constexpr const char* kObjectOfSopInstance = "SELECT object FROM instances WHERE sop_instance_uid = ?1";
// kObjectsOfSopInstancesIn + "?1, ?2..." + ")": a batch's instances already archived, in one
// round trip instead of one per file.
inline constexpr const char* kObjectsOfSopInstancesIn =
    "SELECT sop_instance_uid, object FROM instances WHERE sop_instance_uid IN (";

// ?1 patient_id ?2 name ?3 birth_date ?4 sex ?5 created_at
inline constexpr const char* kInsertPatient =
    "INSERT INTO patients(patient_id, name, birth_date, sex, created_at) VALUES (?1, ?2, ?3, ?4, ?5) "
    "ON CONFLICT(patient_id) DO NOTHING RETURNING id";
inline constexpr const char* kPatientByPatientId =
    "SELECT id, name, birth_date, sex FROM patients WHERE patient_id = ?1";
// ?1 patient ?2 created_at
inline constexpr const char* kInsertDefaultCase =
    "INSERT INTO cases(patient, label, created_at) VALUES (?1, 'default', ?2) ON CONFLICT(patient, label) DO NOTHING "
    "RETURNING id";
// ?1 patient ?2 label ?3 created_at
inline constexpr const char* kInsertLabelledCase =
    "INSERT INTO cases(patient, label, created_at) VALUES (?1, ?2, ?3) ON CONFLICT(patient, label) DO NOTHING "
    "RETURNING id";
inline constexpr const char* kDefaultCaseOfPatient = "SELECT id FROM cases WHERE patient = ?1 AND label = 'default'";
// ?1 patient ?2 attribute ?3 archived ?4 arrived ?5 source_path ?6 sop_instance_uid ?7 flagged_at
inline constexpr const char* kInsertIdentityFlag =
    "INSERT INTO identity_flags(patient, attribute, archived_value, arrived_value, source_path, "
    "sop_instance_uid, flagged_at) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7) ON CONFLICT DO NOTHING RETURNING id";
// ?1 patient ?2 study_uid ?3 date ?4 time ?5 description ?6 accession
inline constexpr const char* kInsertStudy =
    "INSERT INTO studies(patient, study_uid, date, time, description, accession) VALUES (?1, ?2, ?3, ?4, ?5, ?6) "
    "ON CONFLICT(study_uid) DO NOTHING RETURNING id";
inline constexpr const char* kStudyIdByUid = "SELECT id FROM studies WHERE study_uid = ?1";
// ?1 study ?2 series_uid ?3 modality ?4 description ?5 number ?6 rows ?7 columns ?8 ?9 spacing ?10 thickness
inline constexpr const char* kInsertSeries =
    "INSERT INTO series(study, series_uid, modality, description, number, rows, columns, pixel_spacing_row, "
    "pixel_spacing_column, slice_thickness) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10) "
    "ON CONFLICT(series_uid) DO NOTHING RETURNING id";
inline constexpr const char* kSeriesIdByUid = "SELECT id FROM series WHERE series_uid = ?1";
// ?1 case: an update that changes nothing, for the row lock it takes on a server (held until
// COMMIT), so that writers attaching series to one case take turns (SQLite: one writer anyway).
inline constexpr const char* kLockCase = "UPDATE cases SET label = label WHERE id = ?1";
// ?1 case ?2 series ?3 modality: the first CT series of a case is its pre-operative scan.
inline constexpr const char* kAttachSeriesToCase =
    "INSERT INTO case_series(case_id, series, role) VALUES (?1, ?2, "
    "CASE WHEN ?3 = 'CT' AND NOT EXISTS (SELECT 1 FROM case_series WHERE case_id = ?1 AND role = 'preop') "
    "THEN 'preop' ELSE 'unassigned' END) ON CONFLICT DO NOTHING";
// ?1 sha256 ?2 size
// RETURNING *: the new row, for the journal without a second read (a round trip on a server).
inline constexpr const char* kInsertObject =
    "INSERT INTO objects(sha256, size) VALUES (?1, ?2) ON CONFLICT DO NOTHING RETURNING *";
// ?1 series ?2 sop_instance_uid ?3 sop_class ?4 number ?5 position ?6 orientation ?7 syntax ?8 object
// ?9 size ?10 source_path ?11 imported_at
inline constexpr const char* kInsertInstance =
    "INSERT INTO instances(series, sop_instance_uid, sop_class_uid, instance_number, image_position, "
    "image_orientation, transfer_syntax, object, size, source_path, imported_at) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11) ON CONFLICT(sop_instance_uid) DO NOTHING RETURNING *";
// The same for many rows in one round trip: head + db::value_rows(rows, columns) + tail, each
// row's parameters (kObjectColumnCount, kInstanceColumnCount of them) in kInsertObject's and
// kInsertInstance's order.
inline constexpr const char* kInsertObjectsHead = "INSERT INTO objects(sha256, size) VALUES ";
inline constexpr int kObjectColumnCount = 2;
inline constexpr const char* kInsertObjectsTail = " ON CONFLICT DO NOTHING RETURNING *";
inline constexpr const char* kInsertInstancesHead =
    "INSERT INTO instances(series, sop_instance_uid, sop_class_uid, instance_number, image_position, "
    "image_orientation, transfer_syntax, object, size, source_path, imported_at) VALUES ";
inline constexpr int kInstanceColumnCount = 11;
inline constexpr const char* kInsertInstancesTail = " ON CONFLICT(sop_instance_uid) DO NOTHING RETURNING *";

// --- listing ---
inline constexpr const char* kPatients =
    "SELECT p.id, p.patient_id, p.name, p.birth_date, p.sex, "
    "(SELECT COUNT(*) FROM studies s WHERE s.patient = p.id) FROM patients p";
inline constexpr const char* kStudies =
    "SELECT s.id, s.patient, s.study_uid, s.date, s.time, s.description, s.accession, "
    "(SELECT COUNT(*) FROM series x WHERE x.study = s.id) FROM studies s";
inline constexpr const char* kSeries =
    "SELECT x.id, x.study, x.series_uid, x.modality, x.description, x.number, x.rows, x.columns, "
    "x.pixel_spacing_row, x.pixel_spacing_column, x.slice_thickness, "
    "(SELECT COUNT(*) FROM instances i WHERE i.series = x.id) FROM series x";
inline constexpr const char* kInstanceColumns =
    "SELECT id, series, sop_instance_uid, sop_class_uid, instance_number, image_position, image_orientation, "
    "transfer_syntax, object, size, source_path, imported_at FROM instances ";
// kObjectsOfSeriesIn + "?1, ?2..." + ")": the objects of several series with what orders them
// (kOfSeriesInOrder's order). Unsorted: sorting a whole archive's instances is the server's
// slowest step (a spill to disk), and the client sorts each series' few hundred rows cheaply.
inline constexpr const char* kObjectsOfSeriesIn =
    "SELECT series, object, instance_number, id FROM instances WHERE series IN (";
inline constexpr const char* kOfSeriesInOrder =
    "WHERE series = ?1 ORDER BY instance_number IS NULL, instance_number, id";
inline constexpr const char* kWithId = "WHERE id = ?1";
inline constexpr const char* kCases = "SELECT id, patient, label, created_at FROM cases";
inline constexpr const char* kIdentityFlags =
    "SELECT id, patient, attribute, archived_value, arrived_value, source_path, sop_instance_uid, flagged_at "
    "FROM identity_flags ORDER BY id";
// kCasesWithPatientsIn + "?1, ?2..." + ")": cases with their patient (kPatients's columns),
// label, time and id, in one query.
inline constexpr const char* kCasesWithPatientsIn =
    "SELECT p.id, p.patient_id, p.name, p.birth_date, p.sex, (SELECT COUNT(*) FROM studies s WHERE s.patient = p.id), "
    "c.label, c.created_at, c.id FROM cases c JOIN patients p ON p.id = c.patient WHERE c.id IN (";
// kSeriesOfCasesIn + "?1, ?2..." + ")": the cases' series (kSeries's columns), role and case.
inline constexpr const char* kSeriesOfCasesIn =
    "SELECT x.id, x.study, x.series_uid, x.modality, x.description, x.number, x.rows, x.columns, "
    "x.pixel_spacing_row, x.pixel_spacing_column, x.slice_thickness, "
    "(SELECT COUNT(*) FROM instances i WHERE i.series = x.id), cs.role, cs.case_id "
    "FROM case_series cs JOIN series x ON x.id = cs.series WHERE cs.case_id IN (";
// kStudiesOfCasesIn + "?1, ?2..." + ")": the studies the cases' series belong to (kStudies's
// columns) and the case.
inline constexpr const char* kStudiesOfCasesIn =
    "SELECT DISTINCT s.id, s.patient, s.study_uid, s.date, s.time, s.description, s.accession, "
    "(SELECT COUNT(*) FROM series x WHERE x.study = s.id), cs.case_id "
    "FROM studies s JOIN series y ON y.study = s.id JOIN case_series cs ON cs.series = y.id WHERE cs.case_id IN (";

// --- resolving user-given IDs ---
inline constexpr const char* kPatientIdOf = "SELECT id FROM patients WHERE patient_id = ?1";
inline constexpr const char* kStudyIdOf = "SELECT id FROM studies WHERE study_uid = ?1";
inline constexpr const char* kSeriesIdOf = "SELECT id FROM series WHERE series_uid = ?1";
inline constexpr const char* kInstanceIdOf = "SELECT id FROM instances WHERE sop_instance_uid = ?1";
inline constexpr const char* kExists[] = {"SELECT 1 FROM series WHERE id = ?1", "SELECT 1 FROM studies WHERE id = ?1",
                                          "SELECT 1 FROM patients WHERE id = ?1", "SELECT 1 FROM cases WHERE id = ?1"};

// --- cases ---
inline constexpr const char* kSetSeriesRole = "UPDATE case_series SET role = ?3 WHERE case_id = ?1 AND series = ?2";

// --- artefacts ---
// ?1 case ?2 kind ?3 object ?4 media_type ?5 inputs_hash ?6 parameters ?7 program_version ?8 created_at
inline constexpr const char* kInsertArtefact =
    "INSERT INTO artefacts(case_id, kind, object, media_type, inputs_hash, parameters, program_version, created_at) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8) RETURNING id";
inline constexpr const char* kArtefactColumns =
    "SELECT id, case_id, kind, object, media_type, inputs_hash, parameters, program_version, created_at FROM "
    "artefacts ";
inline constexpr const char* kFindArtefact =
    "WHERE case_id = ?1 AND kind = ?2 AND inputs_hash = ?3 ORDER BY id DESC LIMIT 1";
// kArtefactColumns + kArtefactsOfCasesIn + "?1, ?2..." + kInIdOrder: the artefacts of several cases.
inline constexpr const char* kArtefactsOfCasesIn = "WHERE case_id IN (";
inline constexpr const char* kInIdOrder = ") ORDER BY id";

// --- verify ---
inline constexpr const char* kAllObjects = "SELECT sha256, size FROM objects";
// ?1 sha256: what names this object, for a person to see what a missing or corrupt one affects.
inline constexpr const char* kOwnersOfObject =
    "SELECT 'case:' || COALESCE(CAST(cs.case_id AS TEXT), '?') || ' series:' || i.series || ' instance:' || i.id "
    "FROM instances i LEFT JOIN case_series cs ON cs.series = i.series WHERE i.object = ?1 "
    "UNION ALL SELECT 'case:' || a.case_id || ' artefact:' || a.id || ' (' || a.kind || ')' "
    "FROM artefacts a WHERE a.object = ?1";

// --- work queue (db/003_work_queue.sql) ---
// ?1 queue ?2 item
inline constexpr const char* kOfferWork =
    "INSERT INTO work_queue(queue, item) VALUES (?1, ?2) ON CONFLICT (queue, item) DO NOTHING";
// ?1 queue ?2 now: the first pending item whose lease is free or ended.
#define MAXILLO_CLAIMABLE_WORK \
  "SELECT item FROM work_queue WHERE queue = ?1 AND state = 'pending' AND expires_at <= ?2 ORDER BY item LIMIT 1"
inline constexpr const char* kClaimableWork = MAXILLO_CLAIMABLE_WORK;
inline constexpr const char* kClaimableWorkSkipLocked = MAXILLO_CLAIMABLE_WORK " FOR UPDATE SKIP LOCKED";
#undef MAXILLO_CLAIMABLE_WORK
// ?1 queue ?2 item ?3 holder ?4 expires_at
inline constexpr const char* kLeaseWork =
    "UPDATE work_queue SET holder = ?3, expires_at = ?4, claims = claims + 1 WHERE queue = ?1 AND item = ?2";
inline constexpr const char* kRenewWork =
    "UPDATE work_queue SET expires_at = ?4 WHERE queue = ?1 AND item = ?2 AND holder = ?3 AND state = 'pending'";
// ?1 queue ?2 item ?3 holder ?4 state ?5 reason
inline constexpr const char* kFinishWork =
    "UPDATE work_queue SET state = ?4, reason = ?5 WHERE queue = ?1 AND item = ?2 AND holder = ?3 AND state = "
    "'pending'";
// ?1 queue ?2 now -> pending, leased, finished
inline constexpr const char* kCountWork =
    "SELECT COALESCE(SUM(CASE WHEN state = 'pending' AND expires_at <= ?2 THEN 1 ELSE 0 END), 0), "
    "COALESCE(SUM(CASE WHEN state = 'pending' AND expires_at > ?2 THEN 1 ELSE 0 END), 0), "
    "COALESCE(SUM(CASE WHEN state <> 'pending' THEN 1 ELSE 0 END), 0) FROM work_queue WHERE queue = ?1";
inline constexpr const char* kWorkRecords =
    "SELECT item, state, holder, reason, claims, expires_at FROM work_queue WHERE queue = ?1 ORDER BY item";

}  // namespace maxillo::sql
