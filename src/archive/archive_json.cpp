#include "archive/archive_json.h"

namespace maxillo {
namespace {

template <typename T>
Json optional(const std::optional<T>& value) {
  return value ? Json(*value) : Json(nullptr);
}

template <typename Container>
Json strings(const Container& items) {
  Json list = Json::array();
  for (const auto& item : items) list.push_back(Json(std::string(item)));
  return list;
}

Json paths(const std::vector<std::filesystem::path>& items) {
  Json list = Json::array();
  for (const auto& item : items) list.push_back(item.string());
  return list;
}

}  // namespace

Json to_json(const PatientRecord& r) {
  return {{"id", r.id},   {"patient_id", r.patient_id}, {"name", r.name}, {"birth_date", r.birth_date},
          {"sex", r.sex}, {"studies", r.study_count}};
}

Json to_json(const StudyRecord& r) {
  return {{"id", r.id},     {"patient", r.patient},         {"study_uid", r.study_uid}, {"date", r.date},
          {"time", r.time}, {"description", r.description}, {"accession", r.accession}, {"series", r.series_count}};
}

Json to_json(const SeriesRecord& r) {
  return {{"id", r.id},
          {"study", r.study},
          {"series_uid", r.series_uid},
          {"modality", r.modality},
          {"description", r.description},
          {"number", optional(r.number)},
          {"rows", optional(r.rows)},
          {"columns", optional(r.columns)},
          {"pixel_spacing_mm", {optional(r.pixel_spacing_row), optional(r.pixel_spacing_column)}},
          {"slice_thickness_mm", optional(r.slice_thickness)},
          {"instances", r.instance_count}};
}

Json to_json(const InstanceRecord& r) {
  return {{"id", r.id},
          {"series", r.series},
          {"sop_instance_uid", r.sop_instance_uid},
          {"sop_class_uid", r.sop_class_uid},
          {"instance_number", optional(r.instance_number)},
          {"image_position", r.image_position},
          {"image_orientation", r.image_orientation},
          {"transfer_syntax", r.transfer_syntax},
          {"sha256", r.object_sha256},
          {"size", r.size},
          {"source_path", r.source_path},
          {"imported_at", r.imported_at}};
}

Json to_json(const CaseRecord& r) {
  return {{"id", r.id}, {"patient", r.patient}, {"label", r.label}, {"created_at", r.created_at}};
}

Json to_json(const ArtefactRecord& r) {
  return {{"id", r.id},
          {"kind", r.kind},
          {"sha256", r.object_sha256},
          {"media_type", r.media_type},
          {"inputs_hash", r.inputs_hash},
          {"parameters", Json::parse(r.parameters_json, nullptr, false)},
          {"program_version", r.program_version},
          {"created_at", r.created_at}};
}

Json to_json(const IdentityFlag& r) {
  return {{"id", r.id},
          {"patient", r.patient},
          {"attribute", r.attribute},
          {"archived_value", r.archived_value},
          {"arrived_value", r.arrived_value},
          {"source_path", r.source_path},
          {"sop_instance_uid", r.sop_instance_uid},
          {"flagged_at", r.flagged_at}};
}

Json to_json(const CaseContents& c) {
  Json studies = Json::array(), series = Json::array();
  for (const auto& s : c.studies) studies.push_back(to_json(s));
  for (const auto& s : c.series) {
    Json entry = to_json(s.series);
    entry["role"] = s.role;
    series.push_back(entry);
  }
  Json json = to_json(c.record);
  json["patient"] = to_json(c.patient);
  json["studies"] = studies;
  json["series"] = series;
  return json;
}

Json to_json(const ImportProblem& p) {
  return {{"path", p.path.string()},
          {"outcome", std::string(to_string(p.outcome))},
          {"code", std::string(name_of(p.code))},
          {"reason", p.reason}};
}

Json to_json(const ImportReport& r) {
  Json problems = Json::array();
  for (const auto& p : r.problems) problems.push_back(to_json(p));
  return {{"files", r.files()},       {"imported", r.imported}, {"already_archived", r.already_archived},
          {"conflicts", r.conflicts}, {"failed", r.failed},     {"identity_flags", r.identity_flags},
          {"restored", r.restored},   {"problems", problems}};
}

Json to_json(const VerifyReport& r) {
  Json owners = Json::object();
  for (const auto& [sha, names] : r.owners) owners[sha] = strings(names);
  return {{"index_check", r.index_check},
          {"journal_differences", strings(r.journal_differences)},
          {"objects_checked", r.objects_checked},
          {"consistent", r.consistent()},
          {"data_intact", r.data_intact()},
          {"missing", strings(r.missing)},
          {"corrupt", strings(r.corrupt)},
          {"owners", owners},
          {"orphans", paths(r.orphans)},
          {"temporaries", paths(r.temporaries)},
          {"adopted", paths(r.adopted)},
          {"journal_check_failure", r.journal_check_failure},
          {"quarantined", r.quarantined},
          {"within_grace", r.within_grace},
          {"restored", strings(r.restored)},
          {"repair_refused", r.repair_refused.empty() ? Json(nullptr) : Json(r.repair_refused)}};
}

Json to_json(const MigrationReport& r) {
  return {{"verified", r.verified()},
          {"objects_copied", r.objects_copied},
          {"objects_present", r.objects_present},
          {"damaged_sources", strings(r.damaged_sources)},
          {"journal_entries", r.journal_entries},
          {"journal_problems", strings(r.journal_problems)},
          {"rows", r.rows},
          {"differences", strings(r.differences)}};
}

Json to_json(const RebuildReport& r) {
  return {{"journal_entries", r.journal_entries},
          {"journal_problems", strings(r.journal_problems)},
          {"restored_from_quarantine", r.restored_from_quarantine},
          {"instances_checked", r.instances_checked},
          {"instances_without_object", r.instances_without_object},
          {"disagreements", strings(r.disagreements)},
          {"dicom_adopted", r.dicom_adopted},
          {"unexplained", paths(r.unexplained)},
          {"previous_index", r.previous_index.empty() ? Json(nullptr) : Json(r.previous_index.string())},
          {"rows", r.rows}};
}

}  // namespace maxillo
