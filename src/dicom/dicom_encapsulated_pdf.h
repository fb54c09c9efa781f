#pragma once
// A PDF report as a DICOM Encapsulated PDF instance (PS3.3 A.45.1), in the patient's study, so a
// PACS shows it beside the images it was made from. The report series is one per study and the
// instance UID derives from the PDF's bytes: storing the same report twice changes nothing.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "dicom/patient_study_records.h"

namespace maxillo {

struct EncapsulatedReport {
  PatientRecord patient;       // from the archive: name, ID, birth date, sex
  StudyRecord study;           // the study the report belongs to (UID, date, time, accession)
  std::string document_title;  // e.g. "Consultation report"
  std::string series_description = "maxillo reports";
  int series_number = 9000;  // out of the way of scanner series numbers
};

// Writes the DICOM file to `out` atomically. Returns its SOP Instance UID.
// Throws Error(WriteFailed) naming the file.
std::string write_encapsulated_pdf(std::span<const std::byte> pdf, const EncapsulatedReport& report,
                                   const std::filesystem::path& out);

}  // namespace maxillo
