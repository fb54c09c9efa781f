#pragma once
// A validation's numbers as JSON (validation.json, the "validation" artefact; read back by validation_record.h): the
// consultation report and the nightly summary read the stored document, so a case validated last night is shown
// without recomputing it.
#include <vector>

#include "core/json.h"
#include "pipeline/case_validation.h"

namespace maxillo::pipeline {

Json validation_json(const CaseValidation& validation, const CaseContents& contents);

Json to_json(const validation::DistanceStatistics& s);

}  // namespace maxillo::pipeline
