#pragma once
// Keys that identify how a derived artefact was made. A derivation key is the SHA-256 of the
// inputs' content hashes, the parameters (canonical JSON) and the program version, so an
// artefact stored under a key is up to date exactly when the key computed now is equal.
#include <cstdint>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "core/json.h"

namespace maxillo::records {

// SHA-256 over the object hashes of a series' instances in instance order: names the data.
std::string series_content_hash(const Archive& archive, int64_t series);
// The same for several series, read in a few queries (one per 4,096 series).
std::vector<std::string> series_content_hashes(const Archive& archive, const std::vector<int64_t>& series);

// SHA-256 of (input hashes in order, parameters.dump(), program version).
std::string derivation_key(const std::vector<std::string>& input_hashes, const Json& parameters);

// The series a consultation is about: the case's "preop" series, else its first CT series.
// Throws Error(NotFound) naming the case when it has no CT series.
int64_t primary_series(const CaseContents& contents);

// The date (DICOM DA) of the study holding a series of the case; "" when unknown.
std::string study_date_of(const CaseContents& contents, int64_t series);

}  // namespace maxillo::records
