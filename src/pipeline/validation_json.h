#pragma once
// A validation's numbers as JSON (validation.json, the "validation" artefact), and back: the consultation report and
// the nightly summary read the stored document, so a case validated last night is shown without recomputing it.
#include <vector>

#include "core/json.h"
#include "pipeline/case_validation.h"

namespace maxillo::pipeline {

Json validation_json(const CaseValidation& validation, const CaseContents& contents);

Json to_json(const validation::DistanceStatistics& s);
validation::DistanceStatistics statistics_from_json(const Json& j);

// The per-region statistics of a stored document ("face" first); closest or corresponding.
struct StoredRegion {
  std::string region;
  validation::DistanceStatistics closest, corresponding;
};
std::vector<StoredRegion> stored_regions(const Json& validation);

}  // namespace maxillo::pipeline
