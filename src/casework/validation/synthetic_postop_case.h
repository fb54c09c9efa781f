#pragma once
// `maxillo sample-postop CASE`: the synthetic post-operative CT of a planned case (see synthetic_postop.h) written as
// a DICOM series of the same patient, a truth file with the answer a validation must find, and optionally imported
// into the archive as the case's post-operative series.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "archive/archive.h"
#include "core/json.h"
#include "casework/validation/synthetic_postop.h"

namespace maxillo::casework {

struct SyntheticPostopCase {
  SyntheticPostop postop;
  std::filesystem::path dicom_folder;  // OUT/ct
  std::filesystem::path truth_json;    // OUT/truth.json
  std::string series_uid;
  std::optional<int64_t> series;  // the archived series, when imported
  Json truth;
};

// `study_date`: YYYYMMDD of the post-operative scan (empty: the pre-operative date + 1 year). `planned`: the case as
// load_planned_case gives it, when the caller has it already.
SyntheticPostopCase make_synthetic_postop_case(Archive& archive, int64_t case_id, const SyntheticPostopOptions& options,
                                               const std::filesystem::path& out, bool import_into_archive,
                                               const std::string& study_date = "",
                                               const PlannedCase* planned = nullptr);

}  // namespace maxillo::casework
