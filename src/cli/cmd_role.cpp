// maxillo role SERIES ROLE: what a series is for in its patient's case (preop, postop, follow-up, unassigned), e.g.
// to mark the post-operative CT that `maxillo validate` compares with.
#include <iostream>

#include "archive/archive.h"
#include "cli/command.h"
#include "core/error.h"

namespace maxillo::cli {
namespace {

struct RoleArguments {
  std::string series_text;
  std::string role;
  std::string case_text;  // default: the patient's default case
};

int run(const RoleArguments& a, const GlobalOptions& global) {
  auto archive = Archive::open(resolve_archive_dir(global));
  const int64_t series = archive.resolve_series(a.series_text);
  int64_t case_id = 0;
  if (!a.case_text.empty()) {
    case_id = archive.resolve_case(a.case_text);
  } else {
    const auto study = archive.study(archive.series_by_id(series)->study);
    const auto found = archive.case_of_patient(study->patient);
    if (!found)
      throw Error(ErrorCode::kNotFound, a.series_text, "the series' patient has no default case: give --case");
    case_id = found->id;
  }
  archive.set_series_role(case_id, series, a.role);
  std::cout << "series " << series << " is now " << a.role << " in case " << case_id << "\n";
  return 0;
}

}  // namespace

void attach_role(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<RoleArguments>();
  app.add_option("SERIES", a->series_text, "series id or Series Instance UID")->required();
  app.add_option("ROLE", a->role, "preop, postop, follow-up or unassigned")
      ->check(CLI::IsMember({"preop", "postop", "follow-up", "unassigned"}))
      ->required();
  app.add_option("--case", a->case_text, "the case (default: the patient's default case)");
  app.callback([a, &ctx] { ctx.exit_code = run(*a, ctx.global); });
}

}  // namespace maxillo::cli
