#pragma once
// The consultation report as a DICOM Encapsulated PDF in the patient's study: written to a file
// for a PACS, and optionally imported into the archive (a "report" series of the study the
// report analysed), where `maxillo export` hands it on like any series.
#include <cstdint>
#include <filesystem>
#include <string>

#include "archive/archive.h"

namespace maxillo::consultation {

enum class StoreInArchive { Yes, No };

struct ReportDicom {
  std::filesystem::path file;
  std::string sop_instance_uid;
  std::string series_instance_uid;
};

// Wraps report_pdf for the case's analysed study and writes it to dicom_out. With
// StoreInArchive::Yes it is also imported and given the role "report" in the case.
ReportDicom write_report_dicom(Archive& archive, int64_t case_id, const std::filesystem::path& report_pdf,
                               const std::filesystem::path& dicom_out, StoreInArchive store);

}  // namespace maxillo::consultation
