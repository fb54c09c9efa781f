// maxillo validate CASE [--out DIR]: the case's prediction against its post-operative CT
// (pipeline/case_validation.h); the result is stored in the archive under its inputs' hash.
#include <iostream>

#include "cli/command.h"
#include "casework/validation/case_validation.h"
#include "records/validation_archive.h"
#include "casework/validation/validation_json.h"
#include "report/number_text.h"

namespace maxillo::cli {
namespace {

struct ValidateOptions {
  std::string case_text;
  std::filesystem::path out = "validation";
  std::string model = "mtm";
  bool no_correspondence = false;
  bool force = false;
};

casework::ValidationOptions validation_options(const ValidateOptions& o) {
  casework::ValidationOptions options;
  options.soft_tissue.model = *softtissue::parse_model(o.model);
  options.corresponding_points = !o.no_correspondence;
  return options;
}

void print_summary(const casework::CaseValidation& v) {
  using report::fixed;
  std::cout << "registration: " << v.registration.iterations << " iterations, " << fixed(v.registration.seconds, 1)
            << " s; cranium ICP residual " << fixed(v.cranium_icp_rms_mm, 3) << " mm\n";
  for (const auto& s : v.segments)
    std::cout << "segment " << planning::segment_name(planning::Segment(s.segment))
              << ": actual differs from planned by " << fixed(s.mean_difference_mm, 2) << " mm mean, "
              << fixed(s.max_difference_mm, 2) << " mm max\n";
  std::cout << "closest-point distance (mm):  region  n  mean|d|  mean  SD  P5  P50  P95  max|d|  within 2 mm\n";
  for (const auto& r : v.statistics) {
    const auto& s = r.closest;
    std::cout << "  " << r.region << "  " << s.count << "  " << fixed(s.mean_absolute, 2) << "  "
              << fixed(s.mean_signed, 2) << "  " << fixed(s.standard_deviation, 2) << "  " << fixed(s.p5, 2) << "  "
              << fixed(s.p50, 2) << "  " << fixed(s.p95, 2) << "  " << fixed(s.max_absolute, 2) << "  "
              << fixed(s.within_tolerance_percent, 1) << " %\n";
  }
  if (!v.statistics.empty() && v.statistics.front().corresponding.count > 0) {
    const auto& s = v.statistics.front().corresponding;
    std::cout << "corresponding-point distance, face: mean|d| " << fixed(s.mean_absolute, 2) << ", mean "
              << fixed(s.mean_signed, 2) << ", P95 " << fixed(s.p95, 2) << " mm\n";
  }
  std::cout << "took " << fixed(v.seconds, 1) << " s\n";
}

int run_validate(const ValidateOptions& o, const GlobalOptions& global) {
  auto archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(o.case_text);
  const auto options = validation_options(o);
  const auto key = casework::validation_inputs_hash(archive, case_id, options);
  const auto stored = o.force || !key ? std::nullopt : records::find_validation(archive, case_id, *key);
  if (stored) {
    if (global.json)
      std::cout << stored->document.dump(2) << "\n";
    else
      std::cout << "case " << case_id << ": validation up to date (inputs unchanged); --force recomputes it\n";
    return 0;
  }
  const auto validation = casework::validate_case(archive, case_id, options, o.out);
  records::store_validation(archive, casework::validation_to_store(validation));
  if (global.json)
    std::cout << validation.summary.dump(2) << "\n";
  else
    print_summary(validation);
  return 0;
}

}  // namespace

void attach_validate(CLI::App& app, CommandContext& ctx) {
  auto o = std::make_shared<ValidateOptions>();
  app.add_option("CASE", o->case_text, "case id, or a Patient ID (its default case)")->required();
  app.add_option("--out", o->out, "output folder: error maps, profile, skins with distances, validation.json")
      ->capture_default_str();
  app.add_option("--model", o->model, "soft tissue model of the prediction: " + softtissue::model_choices())
      ->check(CLI::IsMember(softtissue::model_names()))
      ->capture_default_str();
  app.add_flag("--no-correspondence", o->no_correspondence,
               "skip the corresponding-point distance (non-rigid registration)");
  app.add_flag("--force", o->force, "recompute even when a validation of the same inputs is stored");
  app.callback([o, &ctx] { ctx.exit_code = run_validate(*o, ctx.global); });
}

}  // namespace maxillo::cli
