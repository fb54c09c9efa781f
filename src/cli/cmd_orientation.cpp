// maxillo orientation CASE [--confirm | --reorient]: does the case's CT header agree with the
// anatomy (the face anterior, the vertex superior)? A contradiction stops planning and
// prediction until a person who has looked at the volume confirms it as it is, or, when an
// axis was flipped, has the case's CT reoriented (a corrected copy; the original is kept).
#include <iostream>

#include "casework/landmarks/case_orientation.h"
#include "casework/landmarks/case_reorientation.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

struct OrientationArguments {
  std::string case_text;
  bool confirm = false;
  bool reorient = false;
};

void print_record(const records::OrientationRecord& record, int64_t case_id, const std::string& case_text) {
  std::cout << "case " << case_id << ", series " << record.series << ": " << record.finding << "\n";
  if (!record.confirmed_at.empty())
    std::cout << "confirmed by hand at " << record.confirmed_at << ": planning may use the volume as it is\n";
  else if (!record.trusted())
    std::cout << "planning and prediction refuse this case until the volume is confirmed (`maxillo orientation "
              << case_text << " --confirm`), reoriented when an axis was flipped (`--reorient`), or the scan is "
              << "corrected and imported again\n";
}

void print_reoriented(const casework::ReorientedCase& r) {
  std::cout << "reoriented: the " << r.flipped_axes << " axis" << (r.flipped_axes.size() > 1 ? "es" : "")
            << " flipped back about the volume's centre; series " << r.corrected_series
            << " (the corrected copy) is now the case's pre-operative CT, series " << r.original_series
            << " is kept, unassigned\n";
  if (r.landmarks_mapped) std::cout << "the landmarks given by hand were mapped to the corrected CT\n";
  if (r.landmarks_detected) std::cout << "the automatic landmarks were detected again on the corrected CT\n";
  std::cout << "left and right are as the original header had them: the anatomy cannot show a mirror\n";
}

int run(const OrientationArguments& a, const GlobalOptions& global) {
  Archive archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(a.case_text);
  std::optional<casework::ReorientedCase> reoriented;
  if (a.reorient) reoriented = casework::reorient_case(archive, case_id);
  const auto record = reoriented  ? reoriented->record
                      : a.confirm ? casework::confirm_orientation(archive, case_id)
                                  : casework::case_orientation(archive, case_id);
  if (global.json) {
    Json json = records::to_json(record);
    json["case"] = case_id;
    json["trusted"] = record.trusted();
    if (reoriented)
      json["reoriented"] = {{"flipped_axes", reoriented->flipped_axes},
                            {"original_series", reoriented->original_series},
                            {"corrected_series", reoriented->corrected_series},
                            {"landmarks_mapped", reoriented->landmarks_mapped},
                            {"landmarks_detected", reoriented->landmarks_detected}};
    std::cout << json_text(json) << "\n";
  } else {
    print_record(record, case_id, a.case_text);
    if (reoriented) print_reoriented(*reoriented);
  }
  return record.trusted() ? 0 : exit_code_for(ErrorCode::kBadValue);
}

}  // namespace

void attach_orientation(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<OrientationArguments>();
  app.add_option("CASE", a->case_text, "case id, case:N or Patient ID")->required();
  auto* confirm =
      app.add_flag("--confirm", a->confirm,
                   "you have looked at the volume and it is right as it is: planning may use it despite the check");
  app.add_flag("--reorient", a->reorient,
               "the header flipped an axis (the face posterior or the vertex inferior): store a corrected copy of the "
               "CT (the original is kept) and plan on it; left and right stay as the header had them")
      ->excludes(confirm);
  app.callback([a, &ctx] { ctx.exit_code = run(*a, ctx.global); });
}

}  // namespace maxillo::cli
