#include "consultation/report_dicom.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "dicom/dicom_encapsulated_pdf.h"
#include "dicom/dicom_uid.h"
#include "records/derivation.h"

namespace maxillo::consultation {
namespace {

const StudyRecord& analysed_study(const CaseContents& contents) {
  int64_t series = records::primary_series(contents);
  int64_t study = 0;
  for (const auto& entry : contents.series)
    if (entry.series.id == series) study = entry.series.study;
  for (const auto& s : contents.studies)
    if (s.id == study) return s;
  throw Error(ErrorCode::kArchiveCorrupt, "case " + std::to_string(contents.record.id), "series without its study");
}

}  // namespace

ReportDicom write_report_dicom(Archive& archive, int64_t case_id, const std::filesystem::path& report_pdf,
                               const std::filesystem::path& dicom_out, StoreInArchive store) {
  auto contents = archive.case_contents(case_id);
  EncapsulatedReport report{contents.patient, analysed_study(contents), "Consultation report"};
  ReportDicom result;
  result.file = dicom_out;
  result.sop_instance_uid = write_encapsulated_pdf(read_file(report_pdf), report, dicom_out);
  result.series_instance_uid = derived_uid("maxillo reports of study " + report.study.study_uid);
  if (store == StoreInArchive::Yes) {
    ImportOptions quiet;
    quiet.progress = ProgressDisplay::Never;
    auto imported = archive.import_paths({dicom_out}, quiet);
    if (!imported.all_ok())
      throw Error(ErrorCode::kProcessing, dicom_out.string(),
                  "the report did not import: " + imported.problems[0].reason);
    archive.set_series_role(case_id, archive.resolve_series(result.series_instance_uid), "report");
  }
  return result;
}

}  // namespace maxillo::consultation
