// maxillo orientation CASE [--confirm]: does the case's CT header agree with the anatomy (the
// face anterior, the vertex superior)? A contradiction stops planning and prediction until a
// person who has looked at the volume confirms it as it is.
#include <iostream>

#include "casework/case_orientation.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

struct OrientationArguments {
  std::string case_text;
  bool confirm = false;
};

int run(const OrientationArguments& a, const GlobalOptions& global) {
  Archive archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(a.case_text);
  const auto record =
      a.confirm ? casework::confirm_orientation(archive, case_id) : casework::case_orientation(archive, case_id);
  if (global.json) {
    Json json = records::to_json(record);
    json["case"] = case_id;
    json["trusted"] = record.trusted();
    std::cout << json_text(json) << "\n";
  } else {
    std::cout << "case " << case_id << ", series " << record.series << ": " << record.finding << "\n";
    if (!record.confirmed_at.empty())
      std::cout << "confirmed by hand at " << record.confirmed_at << ": planning may use the volume as it is\n";
    else if (!record.trusted())
      std::cout << "planning and prediction refuse this case until the volume is confirmed (`maxillo orientation "
                << a.case_text << " --confirm`) or the scan is corrected and imported again\n";
  }
  return record.trusted() ? 0 : exit_code_for(ErrorCode::kBadValue);
}

}  // namespace

void attach_orientation(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<OrientationArguments>();
  app.add_option("CASE", a->case_text, "case id, case:N or Patient ID")->required();
  app.add_flag("--confirm", a->confirm,
               "you have looked at the volume and it is right as it is: planning may use it despite the check");
  app.callback([a, &ctx] { ctx.exit_code = run(*a, ctx.global); });
}

}  // namespace maxillo::cli
