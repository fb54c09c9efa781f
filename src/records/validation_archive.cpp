#include "records/validation_archive.h"

#include <cmath>

#include "archive/artefact_kind.h"
#include "records/stored_artefact.h"

namespace maxillo::records {
namespace {

const std::string kValidationKind = kind_name(ArtefactKind::kValidation);
const std::string kDistancesKind = kind_name(ArtefactKind::kValidationDistances);

Json face_distances_json(const ValidationToStore& v) {
  Json closest = Json::array(), regions = Json::array();
  for (size_t i = 0; i < v.face_closest_mm.size(); ++i) {
    if (std::isnan(v.face_closest_mm[i])) continue;
    closest.push_back(std::round(v.face_closest_mm[i] * 1000) / 1000);  // micrometres are plenty
    regions.push_back(v.face_regions.at(i));
  }
  return Json{{"closest_mm", closest}, {"region", regions}};
}

// `artefacts`: the case's, among them the summary's pictures and distances.
std::optional<StoredValidation> load(const Archive& archive, const std::vector<ArtefactRecord>& artefacts,
                                     const ArtefactRecord& summary) {
  StoredValidation stored;
  stored.case_id = summary.case_id;
  stored.document = artefact_json(archive, summary);
  stored.record = read_validation_record(stored.document, artefact_source(summary));
  for (const char* view : {"error-map-frontal", "error-map-lateral", "error-map-oblique"}) {
    const ArtefactRecord* image = newest_with_key(artefacts, ArtefactKind::kValidationImage, summary.inputs_hash, view);
    if (!image) return std::nullopt;
    stored.error_maps.push_back(archive.object_path(image->object_sha256));
  }
  const ArtefactRecord* profile =
      newest_with_key(artefacts, ArtefactKind::kValidationImage, summary.inputs_hash, "profile");
  const ArtefactRecord* distances = newest_with_key(artefacts, ArtefactKind::kValidationDistances, summary.inputs_hash);
  if (!profile || !distances) return std::nullopt;
  stored.profile = archive.object_path(profile->object_sha256);
  const Json face = artefact_json(archive, *distances);
  stored.face_closest_mm = face.at("closest_mm").get<std::vector<double>>();
  stored.face_regions = face.at("region").get<std::vector<std::string>>();
  return stored;
}

}  // namespace

void store_validation(Archive& archive, const ValidationToStore& v) {
  for (const auto& png : v.pictures)
    store_picture(archive, v.case_id, ArtefactKind::kValidationImage, v.inputs_hash, png);
  archive.add_artefact(NewArtefact{v.case_id, kDistancesKind, archive.store_object(face_distances_json(v).dump()),
                                   "application/json", v.inputs_hash});
  archive.add_artefact(NewArtefact{v.case_id, kValidationKind, archive.store_object(v.summary.dump()),
                                   "application/json", v.inputs_hash});
}

std::optional<StoredValidation> find_validation(const Archive& archive, int64_t case_id,
                                                const std::string& inputs_hash) {
  return find_validation(archive, archive.artefacts(case_id), inputs_hash);  // one query: load needs them all
}

std::optional<StoredValidation> find_validation(const Archive& archive,
                                                const std::vector<ArtefactRecord>& case_artefacts,
                                                const std::string& inputs_hash) {
  const ArtefactRecord* summary = newest_with_key(case_artefacts, ArtefactKind::kValidation, inputs_hash);
  if (!summary) return std::nullopt;
  return load(archive, case_artefacts, *summary);
}

std::optional<StoredValidation> latest_validation(const Archive& archive, int64_t case_id) {
  const auto artefacts = archive.artefacts(case_id);
  const ArtefactRecord* found = newest_artefact(artefacts, kValidationKind);
  if (!found) return std::nullopt;
  return load(archive, artefacts, *found);
}

}  // namespace maxillo::records
