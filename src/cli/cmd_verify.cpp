// maxillo verify [--repair]: re-hash every archived object. Exit 0 when consistent (after
// --repair: when no data is missing or corrupt), else 41 (archive inconsistent).
#include <iostream>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "cli/command.h"

namespace maxillo::cli {

void attach_verify(CLI::App& app, CommandContext& ctx) {
  auto repair = std::make_shared<bool>(false);
  app.add_flag("--repair", *repair, "remove orphan objects and temporary files (never archived data)");
  app.callback([repair, &ctx] {
    Archive archive = Archive::open(resolve_archive_dir(ctx.global));
    VerifyReport report = archive.verify(*repair ? RepairMode::Repair : RepairMode::ReportOnly,
                                         ctx.global.quiet ? ProgressDisplay::Never : ProgressDisplay::Auto);
    bool ok = *repair ? report.data_intact() : report.consistent();
    if (ctx.global.json) {
      Json json = to_json(report);
      json["ok"] = ok;
      std::cout << json.dump(2) << "\n";
    } else {
      for (const auto& sha : report.missing) std::cerr << archive.object_path(sha).string() << ": missing (data loss)\n";
      for (const auto& sha : report.corrupt)
        std::cerr << archive.object_path(sha).string() << ": corrupt (content no longer matches its SHA-256)\n";
      for (const auto& path : report.orphans)
        std::cerr << path.string() << (*repair ? ": orphan object, removed\n" : ": orphan object (verify --repair removes it)\n");
      for (const auto& path : report.temporaries)
        std::cerr << path.string() << (*repair ? ": temporary file, removed\n" : ": temporary file (verify --repair removes it)\n");
      std::cout << report.objects_checked << " objects checked: " << report.missing.size() << " missing, "
                << report.corrupt.size() << " corrupt, " << report.orphans.size() << " orphans, "
                << report.temporaries.size() << " temporary files";
      if (*repair) std::cout << "; " << report.removed << " removed";
      std::cout << (ok ? " - consistent\n" : " - INCONSISTENT\n");
    }
    ctx.exit_code = ok ? 0 : exit_code_for(ErrorCode::kArchiveCorrupt);
  });
}

}  // namespace maxillo::cli
