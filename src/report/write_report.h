#pragma once
// Lays out a ReportModel with a ReportTemplate into a PDF file.
#include <filesystem>

#include "report/report_model.h"
#include "report/report_template.h"

namespace maxillo::report {

// Sections appear in the template's order, each with the template's heading and intro:
// "patient" shows the patient, the case and the series table; the others show the model's
// section of the same id, and are left out when the model has none. The PDF is written
// atomically (temporary file + rename): out_pdf is either absent or complete.
// Throws Error(BadTemplate) when the model has a section the template does not list (naming
// its id), Error(FileNotFound) for a missing font or figure, Error(WriteFailed) otherwise.
// Returns the number of pages written.
int write_report(const ReportModel& model, const ReportTemplate& report_template, const std::filesystem::path& out_pdf);

}  // namespace maxillo::report
