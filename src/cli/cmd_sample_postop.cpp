// maxillo sample-postop CASE --out DIR [--import]: a synthetic post-operative CT of a planned case with a known
// answer (pipeline/synthetic_postop.h), to try and test `maxillo validate`.
#include <iostream>

#include "cli/command.h"
#include "casework/validation/synthetic_postop_case.h"

namespace maxillo::cli {
namespace {

struct SamplePostopArguments {
  std::string case_text;
  std::filesystem::path out;
  casework::SyntheticPostopOptions options;
  std::string date;
  bool import = false;
};

int run(const SamplePostopArguments& a, const GlobalOptions& global) {
  auto archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(a.case_text);
  const auto result = casework::make_synthetic_postop_case(archive, case_id, a.options, a.out, a.import, a.date);
  if (global.json) {
    std::cout << result.truth.dump(2) << "\n";
    return 0;
  }
  std::cout << "wrote " << result.dicom_folder.string() << " (" << result.postop.ct.geometry.size.z() << " slices)\n"
            << "wrote " << result.truth_json.string() << "\n";
  if (result.series)
    std::cout << "imported as series " << *result.series << ", role postop of case " << case_id << "\n";
  return 0;
}

}  // namespace

void attach_sample_postop(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<SamplePostopArguments>();
  app.add_option("CASE", a->case_text, "a case with a CT, landmarks and a plan")->required();
  app.add_option("--out", a->out, "output folder: ct/ (DICOM series) and truth.json")->required();
  app.add_option("--error-mm", a->options.error_mm,
                 "the real face lies this far in front of the prediction at the centre")
      ->check(CLI::Range(-10.0, 10.0))
      ->capture_default_str();
  app.add_option("--error-sigma-mm", a->options.error_sigma_mm, "width (sigma) of that error bump")
      ->check(CLI::Range(1.0, 100.0))
      ->capture_default_str();
  app.add_option("--error-centre", a->options.error_centre, "soft tissue landmark at the bump's centre")
      ->capture_default_str();
  app.add_option("--reposition-deg", a->options.reposition_deg, "head turned in the post-operative scanner")
      ->check(CLI::Range(-30.0, 30.0))
      ->capture_default_str();
  app.add_option("--reposition-mm", a->options.reposition_mm, "and shifted along each axis")
      ->check(CLI::Range(-50.0, 50.0))
      ->capture_default_str();
  app.add_option("--date", a->date, "study date YYYYMMDD (default: a year after the pre-operative CT)");
  app.add_flag("--import", a->import, "import the series into the archive as the case's post-operative CT");
  app.callback([a, &ctx] { ctx.exit_code = run(*a, ctx.global); });
}

}  // namespace maxillo::cli
