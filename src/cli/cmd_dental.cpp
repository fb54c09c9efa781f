// maxillo dental import|register|show CASE (issue 30): a patient's dental scans (an intraoral
// scan or digitised casts, STL/PLY/OBJ in mm) kept with the case and placed onto its CT's teeth
// (casework/occlusion/case_dental_scans.h).
#include <cstdio>
#include <iostream>

#include "casework/occlusion/case_dental_scans.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {
namespace {

using records::DentalArch;

struct DentalArguments {
  std::string case_text;
  std::filesystem::path upper, lower;
};

void print_scan(const records::StoredDentalScan& scan) {
  std::cout << name_of(scan.arch) << " arch: " << scan.source
            << (scan.already_stored ? " is its newest version already (version " : " stored as version ")
            << scan.version << ", artefact " << scan.artefact_id << ")\n";
  for (const auto& warning : scan.warnings) std::cout << "  warning: " << warning << "\n";
}

Json scan_json(const records::StoredDentalScan& scan) {
  return Json{{"arch", name_of(scan.arch)},           {"source", scan.source},         {"version", scan.version},
              {"artefact", scan.artefact_id},         {"created_at", scan.created_at}, {"warnings", scan.warnings},
              {"already_stored", scan.already_stored}};
}

void print_fit(const records::DentalRegistrationRecord& r, const std::string& source, bool reused) {
  std::printf(
      "%s arch (%s): %.0f %% of the scan on the CT's teeth, RMS %.3f mm, P95 %.3f mm, %.0f %% within 0.3 mm, "
      "confidence %.2f; started from %s%s\n",
      std::string(name_of(r.arch)).c_str(), source.c_str(), 100 * r.on_teeth_share, r.rms_mm, r.p95_mm,
      100 * r.within_0_3_share, r.confidence, r.start.c_str(), reused ? " (stored already)" : "");
}

int run_import(const DentalArguments& a, const GlobalOptions& global) {
  if (a.upper.empty() && a.lower.empty()) throw CLI::RequiredError("--upper or --lower");
  Archive archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(a.case_text);
  std::vector<casework::DentalScanFile> files;
  if (!a.upper.empty()) files.push_back({DentalArch::kUpper, a.upper});
  if (!a.lower.empty()) files.push_back({DentalArch::kLower, a.lower});
  const auto stored = casework::import_dental_scans(archive, case_id, files);
  if (global.json) {
    Json json = Json::array();
    for (const auto& scan : stored) json.push_back(scan_json(scan));
    std::cout << json_text(Json{{"case", case_id}, {"scans", json}}) << "\n";
  } else {
    for (const auto& scan : stored) print_scan(scan);
    std::cout << "place them into the CT with `maxillo dental register " << a.case_text << "`\n";
  }
  return 0;
}

int run_register(const DentalArguments& a, const GlobalOptions& global) {
  Archive archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(a.case_text);
  const auto registered = casework::register_case_dental_scans(archive, case_id);
  if (global.json) {
    Json arches = Json::array();
    for (const auto& arch : registered.arches) {
      Json json = records::to_json(arch.record);
      json["source"] = arch.scan.source;
      json["reused"] = arch.reused;
      arches.push_back(json);
    }
    std::cout << json_text(Json{{"case", case_id}, {"arches", arches}}) << "\n";
  } else {
    for (const auto& arch : registered.arches) print_fit(arch.record, arch.scan.source, arch.reused);
  }
  return 0;
}

int run_show(const DentalArguments& a, const GlobalOptions& global) {
  Archive archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(a.case_text);
  Json json{{"case", case_id}};
  for (DentalArch arch : records::kBothArches) {
    Json history = Json::array();
    for (const auto& scan : records::dental_scan_history(archive, case_id, arch)) {
      history.push_back(scan_json(scan));
      if (!global.json) print_scan(scan);
    }
    json[std::string(name_of(arch))] = {{"scans", history}};
    if (const auto registration = records::current_dental_registration(archive, case_id, arch)) {
      json[std::string(name_of(arch))]["registration"] = records::to_json(registration->record);
      if (!global.json) print_fit(registration->record, "newest scan", false);
    } else if (!global.json && !history.empty()) {
      std::cout << name_of(arch) << " arch: its newest scan is not registered yet\n";
    }
  }
  if (global.json) std::cout << json_text(json) << "\n";
  return 0;
}

}  // namespace

void attach_dental(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);
  auto a = std::make_shared<DentalArguments>();
  CLI::App* import = app.add_subcommand("import", "store an arch's scan with the case (a newer version of it)");
  import->add_option("CASE", a->case_text, "case id, case:N or Patient ID")->required();
  import->add_option("--upper", a->upper, "the upper arch's scan (STL, PLY or OBJ, mm)")->check(CLI::ExistingFile);
  import->add_option("--lower", a->lower, "the lower arch's scan (STL, PLY or OBJ, mm)")->check(CLI::ExistingFile);
  import->callback([a, &ctx] { ctx.exit_code = run_import(*a, ctx.global);
});
CLI::App* reg = app.add_subcommand(
    "register", "place each arch's newest scan onto the CT's teeth (needs the case's landmarks), store the fit");
reg->add_option("CASE", a->case_text, "case id, case:N or Patient ID")->required();
reg->callback([a, &ctx] { ctx.exit_code = run_register(*a, ctx.global); });
CLI::App* show = app.add_subcommand("show", "the case's dental scans, every version, and the current fits");
show->add_option("CASE", a->case_text, "case id, case:N or Patient ID")->required();
show->callback([a, &ctx] { ctx.exit_code = run_show(*a, ctx.global); });
}  // namespace maxillo::cli

}  // namespace maxillo::cli
