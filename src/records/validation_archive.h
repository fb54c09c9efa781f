#pragma once
// Validations in the archive, keyed by their inputs' hash (case_validation.h validation_inputs_hash): the summary
// document ("validation", JSON), the per-vertex distances of the face ("validation-distances", JSON) and the pictures
// ("validation-image", PNG, named in the artefact's parameters). The summary is stored last, so its presence marks a
// complete result: a run killed half-way leaves at most pictures that the next run stores again, never a summary
// without its pictures.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "core/json.h"
#include "records/validation_record.h"

namespace maxillo::records {

struct StoredValidation {
  int64_t case_id = 0;
  Json document;                                  // validation.json's document as stored (validate --json)
  ValidationRecord record;                        // the same, read strictly
  std::vector<std::filesystem::path> error_maps;  // object files (PNG without extension)
  std::filesystem::path profile;
  std::vector<double> face_closest_mm;    // closest-point distances of the face's vertices
  std::vector<std::string> face_regions;  // the region of each
};

// What store_validation writes for one validation (validation_json.h validation_to_store makes
// it from a case's validation).
struct ValidationToStore {
  int64_t case_id = 0;
  std::string inputs_hash;                      // case_validation.h validation_inputs_hash
  Json summary;                                 // validation.json's document
  std::vector<std::filesystem::path> pictures;  // PNGs, each stored under its file's stem ("profile", ...)
  std::vector<double> face_closest_mm;          // per face vertex; NaN (no distance) is left out
  std::vector<std::string> face_regions;        // the region of each, by name
};

void store_validation(Archive& archive, const ValidationToStore& validation);

// The validation of the case made from exactly these inputs, if stored.
std::optional<StoredValidation> find_validation(const Archive& archive, int64_t case_id,
                                                const std::string& inputs_hash);
// The same found among the case's artefacts, read already (the nightly scan's): no query.
std::optional<StoredValidation> find_validation(const Archive& archive,
                                                const std::vector<ArtefactRecord>& case_artefacts,
                                                const std::string& inputs_hash);
// The case's newest stored validation, if any (for the consultation report).
std::optional<StoredValidation> latest_validation(const Archive& archive, int64_t case_id);

}  // namespace maxillo::records
