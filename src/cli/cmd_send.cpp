// maxillo send ITEM... --to AE@HOST:PORT [--deidentify] | --report CASE: C-STORE archived series
// to a PACS or another node: the archived bytes, or de-identified copies; the case's reports as
// their Encapsulated PDFs (`maxillo report CASE --store-dicom` files them in the archive).
#include <iostream>
#include <set>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "cli/command.h"
#include "cli/network_options.h"
#include "core/error.h"
#include "core/temporary_folder.h"
#include "net/store_client.h"

namespace maxillo::cli {
namespace {

struct SendArguments {
  std::vector<std::string> items;
  std::string report_case;
  std::string peer;
  bool deidentify = false;
  net::StoreOptions options;
};

// The series an item names: a series, a study's or patient's series, a case's series.
std::vector<int64_t> series_of(const Archive& archive, const std::string& text) {
  const ResolvedItem item = archive.resolve(text);
  std::vector<int64_t> ids;
  switch (item.kind) {
    case ItemKind::Series: ids.push_back(item.id); break;
    case ItemKind::Study:
      for (const auto& s : archive.series(item.id)) ids.push_back(s.id);
      break;
    case ItemKind::Patient:
      for (const auto& study : archive.studies(item.id))
        for (const auto& s : archive.series(study.id)) ids.push_back(s.id);
      break;
    case ItemKind::Case:
      for (const auto& s : archive.case_contents(item.id).series) ids.push_back(s.series.id);
      break;
    case ItemKind::Instance:
      throw Error(ErrorCode::kUsage, text, "send a series, study, patient or case, not one instance");
  }
  return ids;
}

std::vector<int64_t> report_series(const Archive& archive, const std::string& case_text) {
  std::vector<int64_t> ids;
  for (const auto& s : archive.case_contents(archive.resolve_case(case_text)).series)
    if (s.role == "report") ids.push_back(s.series.id);
  if (ids.empty())
    throw Error(ErrorCode::kNotFound, case_text,
                "the case has no report in the archive: run `maxillo report CASE --store-dicom`");
  return ids;
}

void run_send(const SendArguments& a, CommandContext& ctx) {
  const net::DicomPeer peer = net::parse_peer(a.peer);
  if (a.items.empty() && a.report_case.empty())
    throw Error(ErrorCode::kUsage, "send", "give ITEMs to send, or --report CASE");
  const Archive archive = Archive::open(resolve_archive_dir(ctx.global));
  std::vector<int64_t> series = a.report_case.empty() ? std::vector<int64_t>{} : report_series(archive, a.report_case);
  for (const auto& text : a.items)
    for (int64_t id : series_of(archive, text)) series.push_back(id);
  std::set<int64_t> seen;
  std::vector<std::filesystem::path> files;
  const TemporaryFolder scratch("maxillo-send");  // de-identified copies, removed when done
  size_t withheld = 0;                            // series that cannot leave de-identified: named, and the rest sent
  for (int64_t id : series) {
    if (!seen.insert(id).second) continue;
    try {
      const auto these = a.deidentify
                             ? archive.export_series(id, scratch / std::to_string(id), ExportProfile::Deidentified)
                             : archive.series_instance_files(id);
      files.insert(files.end(), these.begin(), these.end());
    } catch (const Error& e) {
      if (e.code() != ErrorCode::kCannotDeidentify) throw;
      std::cerr << e.what() << "; not sent\n";
      ++withheld;
    }
  }
  net::StoreOptions options = a.options;
  options.progress = ctx.global.quiet || ctx.global.json ? ProgressDisplay::Never : ProgressDisplay::Auto;
  const net::StoreReport report = net::send_files(peer, files, options);
  for (const auto& failure : report.failures) std::cerr << failure.file.string() << ": " << failure.reason << "\n";
  if (ctx.global.json) {
    std::cout << json_text(Json{{"peer", net::to_string(peer)},
                                {"sent", report.sent},
                                {"failed", report.failures.size()},
                                {"seconds", report.seconds},
                                {"deidentified", a.deidentify},
                                {"series_withheld", withheld}})
              << "\n";
  } else {
    std::cout << "sent " << report.sent << " instances" << (a.deidentify ? " (de-identified)" : "") << " to "
              << net::to_string(peer) << " in " << report.seconds << " s; " << report.failures.size() << " refused";
    if (withheld) std::cout << "; " << withheld << " series withheld (cannot be de-identified)";
    std::cout << "\n";
  }
  ctx.exit_code = report.failures.empty() && !withheld ? 0 : exit_code_for(ErrorCode::kBatchPartlyFailed);
}

}  // namespace

void attach_send(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<SendArguments>();
  app.add_option("ITEM", a->items, "series, study, patient or case (any id or UID `maxillo show` takes)");
  app.add_option("--report", a->report_case, "send the case's reports (Encapsulated PDF series)");
  app.add_option("--to", a->peer, "the peer: AE@HOST:PORT")->required();
  app.add_flag("--deidentify", a->deidentify,
               "send de-identified copies (as `export --deidentify`) instead of the archived bytes");
  add_requestor_options(app, a->options.calling_ae, a->options.timeout_seconds, a->options.tls);
  app.callback([a, &ctx] { run_send(*a, ctx); });
}

}  // namespace maxillo::cli
