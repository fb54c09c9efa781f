#pragma once
// A validation's numbers as JSON (validation.json, the "validation" artefact; read back by validation_record.h): the
// consultation report and the nightly summary read the stored document, so a case validated last night is shown
// without recomputing it.
#include <vector>

#include "core/json.h"
#include "casework/validation/case_validation.h"
#include "records/validation_archive.h"

namespace maxillo::casework {

Json validation_json(const CaseValidation& validation, const CaseContents& contents);

Json to_json(const validation::DistanceStatistics& s);

// What the archive keeps of `validation` (validation_archive.h store_validation).
records::ValidationToStore validation_to_store(const CaseValidation& validation);

}  // namespace maxillo::casework
