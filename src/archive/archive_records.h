#pragma once
// Plain records the archive returns: rows of the index (db/001_initial.sql), no toolkit types.
// `id` fields are archive ids (SQLite rowids), stable for the life of the archive.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dicom/patient_study_records.h"  // PatientRecord, StudyRecord

namespace maxillo {

struct SeriesRecord {
  int64_t id = 0;
  int64_t study = 0;
  std::string series_uid;
  std::string modality;
  std::string description;
  std::optional<int> number;
  std::optional<int> rows;
  std::optional<int> columns;
  std::optional<double> pixel_spacing_row;     // mm
  std::optional<double> pixel_spacing_column;  // mm
  std::optional<double> slice_thickness;       // mm
  int64_t instance_count = 0;                  // the slice count of a CT series
};

struct InstanceRecord {
  int64_t id = 0;
  int64_t series = 0;
  std::string sop_instance_uid;
  std::string sop_class_uid;
  std::optional<int> instance_number;
  std::string image_position;     // x\y\z, mm, LPS
  std::string image_orientation;  // six direction cosines
  std::string transfer_syntax;
  std::string object_sha256;
  int64_t size = 0;  // bytes
  std::string source_path;
  std::string imported_at;  // UTC ISO 8601
};

struct IdentityFlag {
  int64_t id = 0;
  int64_t patient = 0;
  std::string attribute;  // "name", "birth_date" or "sex"
  std::string archived_value;
  std::string arrived_value;
  std::string source_path;
  std::string sop_instance_uid;
  std::string flagged_at;
};

struct CaseRecord {
  int64_t id = 0;
  int64_t patient = 0;
  std::string label;  // "default" for the case made at first import
  std::string created_at;
};

struct CaseSeries {
  SeriesRecord series;
  std::string role;  // "preop", "postop", "follow-up", "report" (maxillo's own DICOM reports) or "unassigned"
};

// What a report header and its series table need about one case.
struct CaseContents {
  CaseRecord record;
  PatientRecord patient;
  std::vector<StudyRecord> studies;  // by date
  std::vector<CaseSeries> series;    // by study date, then series number
};

enum class ItemKind { Patient, Study, Series, Instance, Case };
std::string to_string(ItemKind kind);

struct ResolvedItem {
  ItemKind kind = ItemKind::Patient;
  int64_t id = 0;
};

struct NewArtefact {
  int64_t case_id = 0;
  std::string kind;           // "report", "render", "surface", "plan", ...
  std::string object_sha256;  // from Archive::store_object
  std::string media_type;     // "application/pdf", "image/png", "model/stl", ...
  std::string inputs_hash;    // sha256 over the inputs (see core/sha256.h Sha256)
  std::string parameters_json = "{}";
};

struct ArtefactRecord {
  int64_t id = 0;
  int64_t case_id = 0;
  std::string kind;
  std::string object_sha256;
  std::string media_type;
  std::string inputs_hash;
  std::string parameters_json;
  std::string program_version;
  std::string created_at;
};

// The newest (highest id) of a case's artefacts of this kind, or nullptr: the current plan,
// landmark set or validation among all the versions a case keeps.
inline const ArtefactRecord* newest_artefact(const std::vector<ArtefactRecord>& artefacts, std::string_view kind) {
  const ArtefactRecord* newest = nullptr;
  for (const auto& a : artefacts)
    if (a.kind == kind && (!newest || a.id > newest->id)) newest = &a;
  return newest;
}

}  // namespace maxillo
