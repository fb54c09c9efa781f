#include "records/stored_artefact.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_reader.h"

namespace maxillo::records {

std::string artefact_source(const ArtefactRecord& artefact) {
  return "artefact " + std::to_string(artefact.id) + " (" + artefact.kind + ")";
}

std::string artefact_text(const Archive& archive, const ArtefactRecord& artefact) {
  const auto bytes = archive.read_object(artefact.object_sha256);
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

Json artefact_json(const Archive& archive, const ArtefactRecord& artefact) {
  Json json = Json::parse(artefact_text(archive, artefact), nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw Error(ErrorCode::kArchiveCorrupt, artefact_source(artefact), "is not JSON");
  return json;
}

void store_picture(Archive& archive, int64_t case_id, ArtefactKind kind, const std::string& inputs_hash,
                   const std::filesystem::path& png) {
  const std::string sha = archive.store_object(read_file(png));
  archive.add_artefact(
      NewArtefact{case_id, kind_name(kind), sha, "image/png", inputs_hash, Json{{"name", png.stem().string()}}.dump()});
}

std::string picture_name(const ArtefactRecord& picture) {
  const std::string source = artefact_source(picture);
  const Json parameters = Json::parse(picture.parameters_json, nullptr, /*allow_exceptions=*/false);
  if (!parameters.is_object()) throw Error(ErrorCode::kArchiveCorrupt, source, "its parameters are not a JSON object");
  JsonReader r(parameters, "", source, ErrorCode::kArchiveCorrupt, "parameters");
  return r.required_text("name");
}

const ArtefactRecord* newest_with_key(const std::vector<ArtefactRecord>& artefacts, ArtefactKind kind,
                                      const std::string& inputs_hash, const std::string& name) {
  const std::string kind_text = kind_name(kind);
  const ArtefactRecord* found = nullptr;
  for (const auto& a : artefacts) {
    if (a.kind != kind_text || a.inputs_hash != inputs_hash) continue;
    if (!name.empty() && picture_name(a) != name) continue;
    if (!found || a.id > found->id) found = &a;
  }
  return found;
}

}  // namespace maxillo::records
