#pragma once
// Reading back what an artefact stored: its object as text or as a JSON document, and the name
// errors give it ("artefact 12 (plan-result)"). A stored document that is not JSON is
// Error(kArchiveCorrupt) naming the artefact, like any other damage to a stored record.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "archive/artefact_kind.h"
#include "core/json.h"

namespace maxillo::records {

std::string artefact_source(const ArtefactRecord& artefact);
std::string artefact_text(const Archive& archive, const ArtefactRecord& artefact);
Json artefact_json(const Archive& archive, const ArtefactRecord& artefact);

// Pictures (PNG) stored as artefacts of `kind` under the inputs' key, each named in its
// parameters by its file's stem ({"name": "error-map-frontal"}), and that name read back
// (Error(kArchiveCorrupt) naming the artefact when its parameters have none).
void store_picture(Archive& archive, int64_t case_id, ArtefactKind kind, const std::string& inputs_hash,
                   const std::filesystem::path& png);
std::string picture_name(const ArtefactRecord& picture);

// The newest of `artefacts` (a case's) of `kind` stored under `inputs_hash` and, when `name` is
// given, named so (a picture); null when there is none.
const ArtefactRecord* newest_with_key(const std::vector<ArtefactRecord>& artefacts, ArtefactKind kind,
                                      const std::string& inputs_hash, const std::string& name = "");

}  // namespace maxillo::records
