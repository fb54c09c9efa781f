// maxillo demo: the whole pipeline on the synthetic phantom, from nothing to a PDF report
// (demo/demo_run.h).
#include <iostream>
#include <map>

#include "cli/command.h"
#include "demo/demo_run.h"

namespace maxillo::cli {

void attach_demo(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<demo::DemoOptions>();
  app.add_option("--out", options->out,
                 "output folder (created): sample/, archive/, report.pdf, nightly/, cohort-followup.pdf")
      ->capture_default_str();
  std::map<std::string, SkeletalClass> classes{
      {"I", SkeletalClass::I}, {"II", SkeletalClass::II}, {"III", SkeletalClass::III}};
  app.add_option("--class", options->skeletal_class, "skeletal class of the phantom: I, II or III")
      ->transform(CLI::CheckedTransformer(classes, CLI::ignore_case));
  app.callback([options, &ctx] {
    options->archive_dir = ctx.global.archive_dir;
    const Json summary = demo::run_demo(*options);
    if (ctx.global.json)
      std::cout << summary.dump(2) << "\n";
    else {
      std::cout << "landmarks found automatically: " << summary["landmarks_detected"].get<int>()
                << ", mean distance from the phantom's known landmarks "
                << summary["landmark_mean_distance_mm"].get<double>() << " mm\n";
      if (!summary["dental_scans"].empty()) {
        std::cout << "dental scans placed into the CT without hands:";
        for (const auto& [arch, fit] : summary["dental_scans"].items())
          std::cout << " " << arch << " " << fit["distance_from_truth_mm"].get<double>() << " mm";
        std::cout << " from where they were taken\n";
      }
      std::cout << "demo report: " << summary["report"].get<std::string>() << " (" << summary["pages"].get<int>()
                << " pages, " << summary["timing"]["total_seconds"].get<double>() << " s)\n";
    }
    ctx.exit_code = 0;
  });
}

}  // namespace maxillo::cli
