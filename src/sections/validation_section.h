#pragma once
// A stored validation as report blocks: the "validation" section of the consultation report, and one page per case of
// the nightly summary (nightly_summary.h).
#include <vector>

#include "records/validation_archive.h"
#include "report/report_model.h"

namespace maxillo::sections {

std::vector<report::Block> validation_blocks(const records::StoredValidation& stored);
report::Section validation_section(const records::StoredValidation& stored);

// The statistics table's columns and one row of it (shared with the summary's cohort table).
std::vector<report::TableColumn> statistics_columns(const std::string& first_column);
std::vector<std::string> statistics_row(const std::string& name, const validation::DistanceStatistics& s);

}  // namespace maxillo::sections
