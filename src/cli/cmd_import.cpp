// maxillo import PATH...: archive DICOM files (folders recursively). One line per bad file on
// stderr ("path: reason"), a summary on stdout, exit 1 when anything failed or conflicted.
#include <iostream>
#include <set>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "casework/landmarks/case_orientation.h"
#include "cli/command.h"
#include "core/error.h"
#include "core/log.h"

namespace maxillo::cli {
namespace {

struct ImportArguments {
  std::vector<std::filesystem::path> paths;
  size_t batch_files = 500;
};

std::string summary_line(const ImportReport& r) {
  if (r.files() > 0 && r.already_archived == r.files() && r.restored == 0)
    return std::to_string(r.already_archived) + " already archived, nothing changed";
  std::string line = std::to_string(r.imported) + " imported, " + std::to_string(r.already_archived) +
                     " already archived, " + std::to_string(r.conflicts) + " conflicts, " + std::to_string(r.failed) +
                     " failed (" + std::to_string(r.files()) + " files)";
  if (r.restored > 0) line += "; " + std::to_string(r.restored) + " lost object files restored";
  if (r.identity_flags > 0)
    line +=
        "; " + std::to_string(r.identity_flags) +
        " identity flags raised (a Patient ID arrived with another name, birth date or sex: see `maxillo list flags`)";
  return line;
}

// Each case that gained images has its CT's header checked against the anatomy now (issue 28),
// so that a contradiction is said at import (a warning naming the case), not first when planning
// refuses. A case whose images make no volume (a report, a single slice) is not checked.
void check_orientations(Archive& archive, const std::set<int64_t>& cases) {
  for (int64_t case_id : cases) {
    try {
      casework::case_orientation(archive, case_id);
    } catch (const Error& e) {
      log::debug("case:", case_id, ": orientation not checked: ", e.what());
    }
  }
}

void run_import(const ImportArguments& args, CommandContext& ctx) {
  Archive archive = Archive::open(resolve_archive_dir(ctx.global), OpenMode::CreateIfMissing);
  ImportOptions options;
  options.batch_files = args.batch_files;
  options.progress = ctx.global.quiet ? ProgressDisplay::Never : ProgressDisplay::Auto;
  options.on_problem = [](const ImportProblem& problem) {
    std::cerr << problem.path.string() << ": " << problem.reason << "\n";
  };
  ImportReport report = archive.import_paths(args.paths, options);
  check_orientations(archive, report.cases_with_new_images);
  if (ctx.global.json)
    std::cout << json_text(to_json(report)) << "\n";
  else
    std::cout << summary_line(report) << "\n";
  ctx.exit_code = report.all_ok() ? 0 : exit_code_for(ErrorCode::kBatchPartlyFailed);
}

}  // namespace

void attach_import(CLI::App& app, CommandContext& ctx) {
  auto args = std::make_shared<ImportArguments>();
  app.add_option("paths", args->paths, "DICOM files or folders (searched recursively)")->required();
  app.add_option("--batch", args->batch_files, "files per durable batch (one sync + one transaction)")
      ->check(CLI::Range(1, 100000));
  app.callback([args, &ctx] { run_import(*args, ctx); });
}

}  // namespace maxillo::cli
