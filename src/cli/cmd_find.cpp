// maxillo find --from AE@HOST:PORT [--patient-id ID] [--name NAME] [--date D] [--modality M]:
// the studies a PACS holds (C-FIND, study level), as a table or --json.
#include <iomanip>
#include <iostream>

#include "archive/archive_json.h"
#include "cli/command.h"
#include "cli/network_options.h"
#include "net/query_client.h"

namespace maxillo::cli {
namespace {

struct FindArguments {
  std::string peer;
  net::StudyQuery query;
  net::QueryOptions options;
};

void run_find(const FindArguments& a, CommandContext& ctx) {
  const auto matches = net::find_studies(net::parse_peer(a.peer), a.query, a.options);
  if (ctx.global.json) {
    Json list = Json::array();
    for (const auto& m : matches)
      list.push_back({{"patient_id", m.patient_id},
                      {"patient_name", m.patient_name},
                      {"study_uid", m.study_uid},
                      {"study_date", m.study_date},
                      {"description", m.study_description},
                      {"modalities", m.modalities},
                      {"accession", m.accession},
                      {"instances", m.instances}});
    std::cout << json_text(list) << "\n";
    return;
  }
  for (const auto& m : matches)
    std::cout << std::left << std::setw(16) << m.patient_id << " " << std::setw(24) << m.patient_name << " "
              << std::setw(8) << m.study_date << " " << std::setw(8) << m.modalities << " " << std::setw(5)
              << m.instances << " " << m.study_uid << "  " << m.study_description << "\n";
  std::cout << matches.size() << " studies\n";
}

}  // namespace

void attach_find(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<FindArguments>();
  app.add_option("--from", a->peer, "the PACS: AE@HOST:PORT")->required();
  app.add_option("--patient-id", a->query.patient_id, "Patient ID (wildcards * and ? allowed)");
  app.add_option("--name", a->query.patient_name, "patient name, DICOM form Family^Given (wildcards allowed)");
  app.add_option("--date", a->query.study_date, "study date YYYYMMDD or range YYYYMMDD-YYYYMMDD");
  app.add_option("--modality", a->query.modality, "a modality in the study, e.g. CT");
  app.add_option("--study", a->query.study_uid, "Study Instance UID");
  add_requestor_options(app, a->options.calling_ae, a->options.timeout_seconds, a->options.tls);
  app.callback([a, &ctx] { run_find(*a, ctx); });
}

}  // namespace maxillo::cli
