#pragma once
// The nightly validation summary PDF: a cohort page (one row of statistics per case, box plots of the signed
// distances per case and per face region) and a page per case (validation_section.h).
#include <filesystem>
#include <string>
#include <vector>

#include "records/validation_archive.h"

namespace maxillo::nightly {

// `run_facts`: lines for the notes (what this run did). Returns the page count. Writes the PDF atomically.
// Error(kEmptyResult) when there is no validation to summarise.
int write_validation_summary(const std::vector<records::StoredValidation>& validations,
                             const std::vector<std::string>& run_facts, const std::filesystem::path& pdf);

}  // namespace maxillo::nightly
