// maxillo ceph measure|add|classify-isbi: cephalometric measurements of a landmark file, landmark
// sets of a case per time point, and the ISBI 2015 class agreement check.
#include <cstdio>
#include <iostream>

#include "ceph/isbi2015.h"
#include "ceph/landmark_io.h"
#include "cli/ceph_options.h"
#include "cli/command.h"
#include "core/error.h"
#include "core/atomic_file.h"
#include "records/case_landmarks.h"
#include "followup/ceph_sample_cohort.h"

namespace maxillo::cli {
namespace {

struct MeasureOptions {
  std::filesystem::path file;
  GeometryOptions geometry;
};

int run_measure(const MeasureOptions& options, const GlobalOptions& global) {
  auto landmarks = read_landmarks(options.file);
  auto sagittal = to_sagittal(landmarks, options.geometry.geometry, options.geometry.axes(), options.file.string());
  auto analysis = ceph::analyse(sagittal, options.geometry.sex);
  if (global.json) {
    Json out = analysis_json(analysis);
    out["file"] = options.file.string();
    std::cout << out.dump(2) << "\n";
  } else {
    print_analysis(analysis);
  }
  return 0;
}

struct AddOptions {
  std::string case_text;
  std::filesystem::path file;
  records::TimePoint time_point;
  GeometryOptions geometry;
};

int run_add(const AddOptions& options, const GlobalOptions& global) {
  auto landmarks = read_landmarks(options.file);
  records::LandmarkFrame frame{options.geometry.geometry, options.geometry.axes()};
  if (frame.geometry == LandmarkGeometry::kAuto) {
    bool planar = !landmarks.empty();
    for (const auto& lm : landmarks) planar = planar && lm.position.z() == 0;
    frame.geometry = planar ? LandmarkGeometry::kCephalogram : LandmarkGeometry::kVolumeLps;
  }
  auto archive = Archive::open(resolve_archive_dir(global));
  auto case_id = archive.resolve_case(options.case_text);
  records::attach_landmarks(archive, case_id, landmarks, options.file.filename().string(), options.time_point, frame);
  int version = 0;
  for (const auto& stored : records::landmark_history(archive, case_id))
    if (stored.time_point.label == options.time_point.label) version = stored.version;
  if (global.json)
    std::cout << Json{{"case", case_id},
                      {"time_point", options.time_point.label},
                      {"date", options.time_point.date},
                      {"landmarks", landmarks.size()},
                      {"version", version}}
                     .dump(2)
              << "\n";
  else
    std::printf("case %lld: %zu landmarks stored for time point '%s' (%s), version %d\n",
                static_cast<long long>(case_id), landmarks.size(), options.time_point.label.c_str(),
                options.time_point.date.empty() ? "no date" : options.time_point.date.c_str(), version);
  return 0;
}

int run_classify_isbi(const std::filesystem::path& table, const GlobalOptions& global) {
  auto images = ceph::read_isbi_landmark_table(table);
  auto agreement = ceph::isbi_class_agreement(images);
  int n = agreement.images;
  if (global.json) {
    std::cout << Json{{"images", n},
                      {"ANB_equal", agreement.anb_equal},
                      {"SNB_equal", agreement.snb_equal},
                      {"SNA_equal", agreement.sna_equal},
                      {"disagreements", agreement.disagreements}}
                     .dump(2)
              << "\n";
  } else {
    std::printf("ISBI 2015 classes from our SNA/SNB/ANB (pixels at %.1f mm, y down), %d images\n",
                ceph::kIsbiPixelSpacingMm, n);
    std::printf("measure  thresholds (class 1)      equal to organisers\n");
    std::printf("ANB      3.2 <= ANB <= 5.7 deg     %d/%d\n", agreement.anb_equal, n);
    std::printf("SNB      74.6 <= SNB <= 78.7 deg   %d/%d\n", agreement.snb_equal, n);
    std::printf("SNA      79.4 <= SNA <= 83.2 deg   %d/%d\n", agreement.sna_equal, n);
    for (const auto& d : agreement.disagreements) std::printf("  differs: %s\n", d.c_str());
  }
  return agreement.disagreements.empty() ? 0 : exit_code_for(ErrorCode::kBatchPartlyFailed);
}

int run_sample_cohort(const std::filesystem::path& out, const GlobalOptions& global) {
  auto cohort = followup::sample_cohort();
  write_file_atomically(out, followup::format_cohort_csv(cohort));
  if (global.json)
    std::cout << Json{{"cohort", out.string()}, {"patients", cohort.size()}}.dump(2) << "\n";
  else
    std::printf("sample cohort: %s (%zu patients, time points pre, post, 6M, 12M, 24M)\n", out.string().c_str(),
                cohort.size());
  return 0;
}

}  // namespace

void attach_ceph(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);

  CLI::App* measure =
      app.add_subcommand("measure", "SNA, SNB, ANB, Wits, nasion-frame positions, alpha of a landmark file");
  measure->fallthrough();
  auto measure_options = std::make_shared<MeasureOptions>();
  measure->add_option("LANDMARKS", measure_options->file, "landmark file: .mrk.json, .fcsv or .csv (label,x,y,z)")
      ->required()
      ->check(CLI::ExistingFile);
  add_geometry_options(*measure, measure_options->geometry);
  measure->callback([measure_options, &ctx] { ctx.exit_code = run_measure(*measure_options, ctx.global); });

  CLI::App* add = app.add_subcommand("add", "store a case's landmark set for a time point (kept with its history)");
  add->fallthrough();
  auto add_options = std::make_shared<AddOptions>();
  add->add_option("CASE", add_options->case_text, "case id, or a Patient ID (its default case)")->required();
  add->add_option("LANDMARKS", add_options->file, "landmark file: .mrk.json, .fcsv or .csv")
      ->required()
      ->check(CLI::ExistingFile);
  add->add_option("--time-point", add_options->time_point.label, "free label: pre, post, 6M, 12M, ...")->required();
  add->add_option("--date", add_options->time_point.date, "date of the image, YYYY-MM-DD")
      ->check(CLI::Validator([](std::string& s) { return records::is_iso_date(s) ? "" : "date must be YYYY-MM-DD"; },
                             "YYYY-MM-DD"));
  add_geometry_options(*add, add_options->geometry);
  add->callback([add_options, &ctx] { ctx.exit_code = run_add(*add_options, ctx.global); });

  CLI::App* isbi =
      app.add_subcommand("classify-isbi", "ISBI 2015 skeletal classes from our SNA/SNB/ANB vs the organisers'");
  isbi->fallthrough();
  auto table = std::make_shared<std::filesystem::path>();
  isbi->add_option("CSV", *table, "isbi2015_train_landmarks.csv")->required()->check(CLI::ExistingFile);
  isbi->callback([table, &ctx] { ctx.exit_code = run_classify_isbi(*table, ctx.global); });

  CLI::App* sample =
      app.add_subcommand("sample-cohort", "write a synthetic follow-up cohort CSV (phantoms, 6 patients)");
  sample->fallthrough();
  auto out = std::make_shared<std::filesystem::path>("cohort.csv");
  sample->add_option("--out", *out, "cohort CSV to write")->capture_default_str();
  sample->callback([out, &ctx] { ctx.exit_code = run_sample_cohort(*out, ctx.global); });
}

}  // namespace maxillo::cli
