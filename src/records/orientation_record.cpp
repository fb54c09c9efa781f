#include "records/orientation_record.h"

#include "archive/artefact_kind.h"
#include "core/json_reader.h"
#include "records/stored_artefact.h"

namespace maxillo::records {
namespace {

std::string verdict_of(const HeadOrientation& found) {
  if (found.contradicts_header()) return "contradicts";
  if (found.face == AxisVerdict::kAsTheHeaderSays && found.vertex == AxisVerdict::kAsTheHeaderSays) return "agrees";
  if (found.face == AxisVerdict::kAsTheHeaderSays || found.vertex == AxisVerdict::kAsTheHeaderSays)
    return "partly confirmed";
  return "undetermined";
}

OrientationRecord read_stored(const Archive& archive, const ArtefactRecord& artefact) {
  return read_orientation_record(artefact_json(archive, artefact), artefact_source(artefact));
}

}  // namespace

OrientationRecord orientation_record(int64_t series, const HeadOrientation& found) {
  OrientationRecord record;
  record.series = series;
  record.verdict = verdict_of(found);
  record.finding = found.finding();
  record.imbalance = found.imbalance;
  record.teeth_cm3 = found.teeth_cm3;
  record.contradicts_header = found.contradicts_header();
  return record;
}

Json to_json(const OrientationRecord& r) {
  return {{"format_version", OrientationRecord::kFormatVersion},
          {"series", r.series},
          {"verdict", r.verdict},
          {"finding", r.finding},
          {"imbalance", {r.imbalance.x(), r.imbalance.y(), r.imbalance.z()}},
          {"teeth_cm3", r.teeth_cm3},
          {"contradicts_header", r.contradicts_header},
          {"confirmed_at", r.confirmed_at}};
}

OrientationRecord read_orientation_record(const Json& json, const std::string& source) {
  if (!json.is_object()) throw Error(ErrorCode::kArchiveCorrupt, source, "an orientation record is a JSON object");
  JsonReader r(json, "", source, ErrorCode::kArchiveCorrupt, "orientation record");
  r.format_version(OrientationRecord::kFormatVersion);
  OrientationRecord record;
  record.series = r.required_integer("series", 1);
  record.verdict = r.required_text("verdict");
  record.finding = r.required_text("finding");
  record.imbalance = r.required_point("imbalance");
  record.teeth_cm3 = r.required_number("teeth_cm3", 0);
  record.contradicts_header = r.required_bool("contradicts_header");
  record.confirmed_at = r.required_text("confirmed_at");
  r.refuse_unknown_keys();
  return record;
}

void store_orientation(Archive& archive, int64_t case_id, const std::string& series_hash,
                       const OrientationRecord& record) {
  const std::string sha = archive.store_object(to_json(record).dump(2) + "\n");
  archive.add_artefact(
      NewArtefact{case_id, kind_name(ArtefactKind::kOrientation), sha, "application/json", series_hash, "{}"});
}

std::optional<OrientationRecord> stored_orientation(const Archive& archive, int64_t case_id,
                                                    const std::string& series_hash) {
  const auto artefacts = archive.artefacts(case_id);
  const ArtefactRecord* newest = newest_with_key(artefacts, ArtefactKind::kOrientation, series_hash);
  if (!newest) return std::nullopt;
  return read_stored(archive, *newest);
}

std::map<int64_t, OrientationRecord> latest_orientations(const Archive& archive, const std::vector<int64_t>& cases) {
  std::map<int64_t, OrientationRecord> found;
  for (const auto& [case_id, artefacts] : archive.artefacts(cases))
    for (auto it = artefacts.rbegin(); it != artefacts.rend(); ++it)
      if (it->kind == kind_name(ArtefactKind::kOrientation)) {
        found.emplace(case_id, read_stored(archive, *it));
        break;
      }
  return found;
}

std::string orientation_summary(const OrientationRecord* record) {
  if (!record) return "-";
  if (record->contradicts_header) return record->confirmed_at.empty() ? "CONTRADICTS" : "confirmed";
  return record->verdict;
}

}  // namespace maxillo::records
