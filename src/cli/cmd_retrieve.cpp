// maxillo retrieve --from AE@HOST:PORT STUDY_UID...: C-GET studies from a PACS into the archive
// (net/retrieve_client.h), archived as `import` would.
#include <iostream>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "cli/command.h"
#include "cli/network_options.h"
#include "core/error.h"
#include "net/retrieve_client.h"

namespace maxillo::cli {
namespace {

struct RetrieveArguments {
  std::string peer;
  std::vector<std::string> studies;
  net::RetrieveOptions options;
};

void run_retrieve(const RetrieveArguments& a, CommandContext& ctx) {
  const net::DicomPeer peer = net::parse_peer(a.peer);
  Archive archive = Archive::open(resolve_archive_dir(ctx.global), OpenMode::CreateIfMissing);
  net::RetrieveOptions options = a.options;
  options.progress = ctx.global.quiet || ctx.global.json ? ProgressDisplay::Never : ProgressDisplay::Auto;
  Json results = Json::array();
  bool all_ok = true;
  for (const auto& study : a.studies) {
    const auto report = net::retrieve_study(peer, study, archive, options);
    for (const auto& problem : report.imported.problems) std::cerr << problem.path.string() << ": " << problem.reason << "\n";
    all_ok &= report.imported.all_ok() && report.failed_by_peer == 0 && report.received > 0;
    if (report.received == 0) std::cerr << study << ": the peer sent nothing (no such study there?)\n";
    results.push_back({{"study", study}, {"received", report.received}, {"failed_at_peer", report.failed_by_peer},
                       {"imported", report.imported.imported}, {"already_archived", report.imported.already_archived},
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
  app.add_option("STUDY", a->studies, "Study Instance UIDs (maxillo find lists them)")->required();
  add_requestor_options(app, a->options.calling_ae, a->options.timeout_seconds, a->options.tls);
  app.callback([a, &ctx] { run_retrieve(*a, ctx); });
}

}  // namespace maxillo::cli
