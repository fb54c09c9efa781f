// maxillo report CASE --out report.pdf: the consultation report of an archived case.
#include <iostream>

#include "cli/command.h"
#include "core/json.h"
#include "consultation/consultation_report.h"
#include "consultation/report_dicom.h"

namespace maxillo::cli {
namespace {

struct ReportOptions {
  std::string case_text;
  std::filesystem::path out = "report.pdf";
  std::string template_resource = "templates/consultation.json";
  std::filesystem::path dicom_out;  // empty: no DICOM copy
  bool store_dicom = false;
};

int run_report(const ReportOptions& options, const GlobalOptions& global) {
  auto archive = Archive::open(resolve_archive_dir(global));
  auto case_id = archive.resolve_case(options.case_text);
  consultation::ConsultationOptions consultation;
  consultation.template_resource = options.template_resource;
  auto result = consultation::write_consultation_report(archive, case_id, options.out, consultation);
  std::optional<consultation::ReportDicom> dicom;
  if (!options.dicom_out.empty() || options.store_dicom) {
    auto file =
        options.dicom_out.empty() ? std::filesystem::path(options.out).replace_extension(".dcm") : options.dicom_out;
    dicom = consultation::write_report_dicom(
        archive, case_id, options.out, file,
        options.store_dicom ? consultation::StoreInArchive::Yes : consultation::StoreInArchive::No);
  }
  if (global.json) {
    std::cout << Json{{"report", result.pdf.string()},
                      {"pages", result.pages},
                      {"case", case_id},
                      {"sha256", result.report_sha256},
                      {"surfaces_reused", result.surfaces_reused},
                      {"seconds",
                       {{"surfaces", result.seconds_surfaces},
                        {"views", result.seconds_views},
                        {"layout", result.seconds_layout}}},
                      {"dicom", dicom ? Json{{"file", dicom->file.string()},
                                             {"sop_instance_uid", dicom->sop_instance_uid},
                                             {"stored", options.store_dicom}}
                                      : Json(nullptr)}}
                     .dump(2)
              << "\n";
  } else {
    std::cout << "report: " << result.pdf.string() << " (" << result.pages << " pages)\n";
    if (dicom)
      std::cout << "DICOM Encapsulated PDF: " << dicom->file.string()
                << (options.store_dicom ? " (stored in the patient's study)" : "") << "\n";
  }
  return 0;
}

}  // namespace

void attach_report(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<ReportOptions>();
  app.add_option("CASE", options->case_text, "case id, or a Patient ID (its default case)")->required();
  app.add_option("--out", options->out, "PDF file to write")->capture_default_str();
  app.add_option("--template", options->template_resource, "template resource (see templates/)")->capture_default_str();
  app.add_option("--dicom", options->dicom_out, "also write the report as a DICOM Encapsulated PDF (for a PACS)");
  app.add_flag("--store-dicom", options->store_dicom,
               "also file the DICOM report into the patient's study in the archive (series role 'report')");
  app.callback([options, &ctx] { ctx.exit_code = run_report(*options, ctx.global); });
}

}  // namespace maxillo::cli
