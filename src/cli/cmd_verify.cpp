// maxillo verify [--repair [--force]] [--purge]: check the index (integrity, journal) and
// re-hash every archived object. Exit 0 when consistent (after --repair: when no data is
// missing or corrupt and the index is intact), else 41 (archive inconsistent); 46 when the
// index itself is damaged.
#include <iostream>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "cli/command.h"

namespace maxillo::cli {
namespace {

struct VerifyArguments {
  bool repair = false;
  bool force = false;
  bool purge = false;
  int64_t grace_seconds = -1;  // the archive's default
};

void print_objects(const Archive& archive, const VerifyReport& report, bool repair) {
  auto owners = [&](const std::string& sha) {
    std::string text;
    for (const auto& owner : report.owners.at(sha)) text += (text.empty() ? " [" : ", ") + owner;
    return text.empty() ? text : text + "]";
  };
  for (const auto& sha : report.missing)
    std::cerr << archive.object_path(sha).string() << ": missing (data loss)" << owners(sha) << "\n";
  for (const auto& sha : report.corrupt)
    std::cerr << archive.object_path(sha).string() << ": corrupt (content no longer matches its SHA-256; "
              << "importing the original file again restores it)" << owners(sha) << "\n";
  const bool moved = repair && report.repair_refused.empty();
  for (const auto& path : report.adopted)
    std::cerr << path.string() << ": a DICOM object an interrupted import left, adopted (indexed from its header)\n";
  for (const auto& path : report.orphans)
    std::cerr << path.string() << (moved ? ": orphan object, moved to quarantine\n" : ": orphan object\n");
  for (const auto& path : report.temporaries)
    std::cerr << path.string() << (moved ? ": temporary file, moved to quarantine\n" : ": temporary file\n");
  for (const auto& sha : report.restored)
    std::cerr << archive.object_path(sha).string() << ": restored from quarantine\n";
}

void print_report(const Archive& archive, const VerifyReport& report, bool repair, bool ok) {
  if (report.index_check != "ok") std::cerr << "index: " << report.index_check << "\n";
  if (!report.journal_check_failure.empty())
    std::cerr << "index: could not be compared with its journal: " << report.journal_check_failure << "\n";
  for (const auto& difference : report.journal_differences) std::cerr << "index: " << difference << "\n";
  print_objects(archive, report, repair);
  if (!report.repair_refused.empty()) std::cerr << "repair refused, nothing changed: " << report.repair_refused << "\n";
  const char* index_state = !report.index_intact()                  ? "DAMAGED"
                            : !report.journal_check_failure.empty() ? "NOT CHECKED against its journal"
                                                                    : "intact";
  std::cout << "index " << index_state << "; " << report.objects_checked
            << " objects checked: " << report.missing.size() << " missing, " << report.corrupt.size() << " corrupt, "
            << report.orphans.size() << " orphans, " << report.temporaries.size() << " temporary files";
  if (repair)
    std::cout << "; " << report.adopted.size() << " adopted, " << report.quarantined << " quarantined, "
              << report.restored.size() << " restored";
  if (repair && report.within_grace > 0)
    std::cout << "; " << report.within_grace << " left in place, younger than the grace period (--grace)";
  std::cout << (ok ? " - consistent\n" : " - INCONSISTENT\n");
  if (!repair && (!report.orphans.empty() || !report.temporaries.empty()))
    std::cout << (report.leftovers_are_few() ? "the orphans and temporary files are what interrupted writes leave "
                                               "(harmless); "
                                             : "")
              << "`maxillo verify --repair` adopts orphan DICOM objects (as importing them again would) and moves "
                 "the rest into the quarantine (nothing is deleted)\n";
}

void run_verify(const VerifyArguments& args, CommandContext& ctx) {
  Archive archive = Archive::open(resolve_archive_dir(ctx.global));
  if (args.purge) {
    size_t purged = archive.purge_quarantine();
    if (ctx.global.json)
      std::cout << json_text(Json{{"purged", purged}}) << "\n";
    else
      std::cout << purged << " quarantined files deleted\n";
    return;
  }
  VerifyOptions options{args.repair ? RepairMode::Repair : RepairMode::ReportOnly, args.force,
                        ctx.global.quiet ? ProgressDisplay::Never : ProgressDisplay::Auto, args.grace_seconds};
  VerifyReport report = archive.verify(options);
  const bool ok = (args.repair ? report.data_intact() : report.consistent()) && report.repair_refused.empty();
  if (ctx.global.json) {
    Json json = to_json(report);
    json["ok"] = ok;
    std::cout << json_text(json) << "\n";
  } else {
    print_report(archive, report, args.repair, ok);
  }
  ErrorCode failure = !report.index_intact()                  ? ErrorCode::kIndexDamaged
                      : !report.journal_check_failure.empty() ? ErrorCode::kDatabase
                                                              : ErrorCode::kArchiveCorrupt;
  ctx.exit_code = ok ? 0 : exit_code_for(failure);
}

}  // namespace

void attach_verify(CLI::App& app, CommandContext& ctx) {
  auto args = std::make_shared<VerifyArguments>();
  app.add_flag("--repair", args->repair,
               "move orphan objects and temporary files into the quarantine, put back quarantined objects the "
               "index names (nothing is ever deleted)");
  app.add_flag("--force", args->force, "with --repair: quarantine orphans even when they are many");
  app.add_option("--grace", args->grace_seconds,
                 "with --repair: leave orphans and temporary files younger than this many seconds (default: 600 on "
                 "an archive on a PostgreSQL server, whose shared folder other nodes write, 0 on an embedded one)")
      ->check(CLI::Range(int64_t(0), int64_t(86400 * 30)));
  app.add_flag("--purge", args->purge, "delete the quarantine (what earlier repairs set aside)")->excludes("--repair");
  app.callback([args, &ctx] {
    if (args->force && !args->repair) throw CLI::ValidationError("--force", "only with --repair");
    run_verify(*args, ctx);
  });
}

}  // namespace maxillo::cli
