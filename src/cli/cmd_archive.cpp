// maxillo archive rebuild-index [--force]: re-create a lost or damaged archive index from the
// object store (the journal of index changes and the DICOM objects themselves). Exit 0 when
// every row came back and every instance agrees with its object, 41 when something could not
// be accounted for (listed), 42 when the index is intact and --force was not given.
// maxillo archive migrate --to ADDRESS: copy the embedded archive into another one (a
// PostgreSQL index with its shared object folder), verified; exit 41 when it does not verify.
#include <iostream>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "archive/archive_location.h"
#include "cli/command.h"

namespace maxillo::cli {
namespace {

bool complete(const RebuildReport& r) {
  return r.journal_problems.empty() && r.disagreements.empty() && r.unexplained.empty() &&
         r.instances_without_object == 0;
}

void print_rebuild(const RebuildReport& r) {
  for (const auto& problem : r.journal_problems) std::cerr << "journal " << problem << "\n";
  for (const auto& disagreement : r.disagreements) std::cerr << disagreement << "\n";
  for (const auto& path : r.unexplained)
    std::cerr << path.string() << ": named by no journal entry and not a DICOM file (left in place)\n";
  std::cout << "index rebuilt: " << r.journal_entries << " journal entries replayed, " << r.instances_checked
            << " instances checked against their DICOM objects, " << r.dicom_adopted
            << " DICOM objects indexed from their headers, " << r.restored_from_quarantine
            << " objects restored from quarantine\n";
  for (const auto& [table, rows] : r.rows) std::cout << "  " << table << ": " << rows << " rows\n";
  if (r.instances_without_object > 0)
    std::cout << r.instances_without_object << " instances have no object file (`maxillo verify` lists them)\n";
  if (!r.previous_index.empty()) std::cout << "the previous index is kept as " << r.previous_index.string() << "\n";
}

void attach_rebuild_index(CLI::App& app, CommandContext& ctx) {
  auto force = std::make_shared<bool>(false);
  app.add_flag("--force", *force, "rebuild even an intact index (the current one is kept beside the new one)");
  app.callback([force, &ctx] {
    RebuildOptions options{*force, ctx.global.quiet ? ProgressDisplay::Never : ProgressDisplay::Auto};
    RebuildReport report = Archive::rebuild_index(resolve_archive_dir(ctx.global), options);
    if (ctx.global.json)
      std::cout << json_text(to_json(report)) << "\n";
    else
      print_rebuild(report);
    ctx.exit_code = complete(report) ? 0 : exit_code_for(ErrorCode::kArchiveCorrupt);
  });
}

void print_migration(const MigrationReport& r, const std::string& target) {
  for (const auto& path : r.damaged_sources) std::cerr << path << ": damaged in the source (not copied)\n";
  for (const auto& problem : r.journal_problems) std::cerr << "journal " << problem << "\n";
  for (const auto& difference : r.differences) std::cerr << "source and target differ in " << difference << "\n";
  std::cout << "migrated into " << target << ": " << r.objects_copied << " objects copied (" << r.objects_present
            << " already there), " << r.journal_entries << " journal entries replayed\n";
  for (const auto& [table, rows] : r.rows) std::cout << "  " << table << ": " << rows << " rows\n";
  std::cout << (r.verified() ? "verified: every object re-hashed, every row the same as the source's\n"
                             : "NOT verified: see above; run the migration again once the source is repaired\n");
}

void attach_migrate(CLI::App& app, CommandContext& ctx) {
  auto target = std::make_shared<std::string>();
  app.add_option("--to", *target,
                 "the target archive: postgresql://USER@HOST:PORT/DATABASE?objects=/shared/folder (or a folder)")
      ->required();
  app.callback([target, &ctx] {
    MigrationOptions options{ctx.global.quiet ? ProgressDisplay::Never : ProgressDisplay::Auto};
    MigrationReport report = Archive::migrate(resolve_archive_dir(ctx.global), *target, options);
    if (ctx.global.json)
      std::cout << json_text(to_json(report)) << "\n";
    else
      print_migration(report, parse_archive_location(*target).shown);
    ctx.exit_code = report.verified() ? 0 : exit_code_for(ErrorCode::kArchiveCorrupt);
  });
}

}  // namespace

void attach_archive(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);
  attach_rebuild_index(
      *app.add_subcommand("rebuild-index", "re-create a lost or damaged index from the object store and its journal")
           ->fallthrough(),
      ctx);
  attach_migrate(*app.add_subcommand("migrate", "copy this embedded archive into a PostgreSQL-indexed one, verified")
                      ->fallthrough(),
                 ctx);
}

}  // namespace maxillo::cli
