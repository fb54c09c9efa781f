#include "records/stored_artefact.h"

#include "core/error.h"

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

}  // namespace maxillo::records
