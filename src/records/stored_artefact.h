#pragma once
// Reading back what an artefact stored: its object as text or as a JSON document, and the name
// errors give it ("artefact 12 (plan-result)"). A stored document that is not JSON is
// Error(kArchiveCorrupt) naming the artefact, like any other damage to a stored record.
#include <string>

#include "archive/archive.h"
#include "core/json.h"

namespace maxillo::records {

std::string artefact_source(const ArtefactRecord& artefact);
std::string artefact_text(const Archive& archive, const ArtefactRecord& artefact);
Json artefact_json(const Archive& archive, const ArtefactRecord& artefact);

}  // namespace maxillo::records
