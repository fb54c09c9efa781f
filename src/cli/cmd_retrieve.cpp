// maxillo retrieve --from AE@HOST:PORT STUDY_UID...|--patient-id ID [--move-port PORT]: studies
// from a PACS into the archive by C-GET, or C-MOVE to us (net/retrieve_client.h), archived as
// `import` would. With --patient-id, the patient's studies are found first (C-FIND).
#include <iostream>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "cli/command.h"
#include "cli/network_options.h"
#include "core/error.h"
#include "net/query_client.h"
#include "net/retrieve_client.h"

namespace maxillo::cli {
namespace {

struct RetrieveArguments {
  std::string peer;
  std::vector<std::string> studies;
  std::string patient_id;
  net::RetrieveOptions options;
};

// The studies named, or those the peer holds for --patient-id.
std::vector<std::string> studies_to_retrieve(const RetrieveArguments& a, const net::DicomPeer& peer) {
  if (a.studies.empty() == a.patient_id.empty())
    throw Error(ErrorCode::kUsage, "retrieve", "give Study Instance UIDs or --patient-id, one of the two");
  if (a.patient_id.empty()) return a.studies;
  const net::QueryOptions query{
      .calling_ae = a.options.calling_ae, .timeout_seconds = a.options.timeout_seconds, .tls = a.options.tls};
  net::StudyQuery of_patient;
  of_patient.patient_id = a.patient_id;
  std::vector<std::string> studies;
  for (const auto& match : net::find_studies(peer, of_patient, query)) studies.push_back(match.study_uid);
  if (studies.empty()) throw Error(ErrorCode::kNotFound, net::to_string(peer), "holds no study for that patient ID");
  return studies;
}

void run_retrieve(const RetrieveArguments& a, CommandContext& ctx) {
  const net::DicomPeer peer = net::parse_peer(a.peer);
  Archive archive = Archive::open(resolve_archive_dir(ctx.global), OpenMode::CreateIfMissing);
  net::RetrieveOptions options = a.options;
  options.progress = ctx.global.quiet || ctx.global.json ? ProgressDisplay::Never : ProgressDisplay::Auto;
  Json results = Json::array();
  bool all_ok = true;
  for (const auto& study : studies_to_retrieve(a, peer)) {
    const auto report = net::retrieve_study(peer, study, archive, options);
    for (const auto& problem : report.imported.problems)
      std::cerr << problem.path.string() << ": " << problem.reason << "\n";
    all_ok &= report.imported.all_ok() && report.failed_by_peer == 0 && report.received > 0;
    if (report.received == 0 && report.sent_by_peer > 0 && options.move_port != 0)
      std::cerr << study << ": the peer says it sent " << report.sent_by_peer << " instances, but none reached "
                << options.calling_ae << " on port " << options.move_port
                << ": the peer knows our AE title at another address or port; configure it with this machine's "
                   "address and the --move-port\n";
    else if (report.received == 0)
      std::cerr << study << ": the peer sent nothing (no such study there?)\n";
    results.push_back({{"study", study},
                       {"received", report.received},
                       {"failed_at_peer", report.failed_by_peer},
                       {"imported", report.imported.imported},
                       {"already_archived", report.imported.already_archived},
                       {"seconds", report.seconds}});
    if (!ctx.global.json)
      std::cout << study << ": " << report.received << " instances received, " << report.imported.imported
                << " archived, " << report.imported.already_archived << " already archived, " << report.failed_by_peer
                << " failed at the peer (" << report.seconds << " s)\n";
  }
  if (ctx.global.json) std::cout << json_text(results) << "\n";
  ctx.exit_code = all_ok ? 0 : exit_code_for(ErrorCode::kBatchPartlyFailed);
}

}  // namespace

void attach_retrieve(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<RetrieveArguments>();
  app.add_option("--from", a->peer, "the PACS: AE@HOST:PORT")->required();
  app.add_option("STUDY", a->studies, "Study Instance UIDs (maxillo find lists them)");
  app.add_option("--patient-id", a->patient_id, "every study the peer holds for this patient");
  app.add_option("--move-port", a->options.move_port,
                 "C-MOVE instead of C-GET: the peer sends to our AE title (--aet), which it must know at this "
                 "machine and port; we listen there for the duration")
      ->check(CLI::Range(1, 65535));
  add_requestor_options(app, a->options.calling_ae, a->options.timeout_seconds, a->options.tls);
  app.callback([a, &ctx] { run_retrieve(*a, ctx); });
}

}  // namespace maxillo::cli
