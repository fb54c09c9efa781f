// maxillo sample --out DIR [--spacing MM] [--class I|II|III] [--patient-id ID]: writes the synthetic craniofacial
// phantom as a DICOM CT series (DIR/ct/) with its analytic landmarks (DIR/landmarks.mrk.json,
// DIR/landmarks.csv; LPS mm). The repository ships no DICOM: this regenerates it in seconds.
// The work is pipeline::write_sample_case (shared with `maxillo demo`).
#include <iostream>
#include <map>

#include "cli/command.h"
#include "core/json.h"
#include "casework/sample_case.h"

namespace maxillo::cli {
namespace {

struct SampleOptions {
  std::filesystem::path out;
  double spacing_mm = 1.0;
  SkeletalClass skeletal_class = SkeletalClass::I;
  std::string patient_id = casework::kPhantomPatientId;
};

void run_sample(const SampleOptions& options, CommandContext& ctx) {
  const casework::SampleCase sample =
      casework::write_sample_case(options.skeletal_class, options.spacing_mm, options.out, options.patient_id);
  const PhantomSpec spec = phantom_spec_for_class(options.skeletal_class);
  const VolumeGeometry& g = sample.geometry;
  const std::string class_name(casework::name_of(options.skeletal_class));
  if (ctx.global.json) {
    Json result = {{"folder", options.out.string()},
                   {"skeletal_class", class_name},
                   {"maxillary_advancement_mm", spec.maxillary_advancement_mm},
                   {"mandibular_protrusion_mm", spec.mandibular_protrusion_mm},
                   {"ct",
                    {{"folder", sample.ct_folder.string()},
                     {"files", sample.series.files.size()},
                     {"size", {g.size.x(), g.size.y(), g.size.z()}},
                     {"spacing_mm", {g.spacing.x(), g.spacing.y(), g.spacing.z()}},
                     {"origin_lps_mm", {g.origin.x(), g.origin.y(), g.origin.z()}},
                     {"study_instance_uid", sample.series.study_instance_uid},
                     {"series_instance_uid", sample.series.series_instance_uid}}},
                   {"landmarks",
                    {{"frame", "LPS"},
                     {"count", sample.landmarks.size()},
                     {"files", {sample.markups_file.string(), sample.csv_file.string()}}}}};
    std::cout << result.dump(2) << "\n";
    return;
  }
  std::cout << "wrote " << sample.series.files.size() << " CT slices of " << g.size.x() << " x " << g.size.y() << " ("
            << g.spacing.x() << " mm, skeletal Class " << class_name << ") to " << sample.ct_folder.string() << "\n"
            << "wrote " << sample.landmarks.size() << " landmarks (LPS mm) to " << sample.markups_file.string()
            << " and " << sample.csv_file.string() << "\n";
}

}  // namespace

void attach_sample(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<SampleOptions>();
  app.add_option("--out", options->out, "output folder (created): ct/, landmarks.mrk.json, landmarks.csv")->required();
  app.add_option("--spacing", options->spacing_mm, "isotropic voxel spacing in mm (0.25 to 4)")
      ->check(CLI::Range(0.25, 4.0))
      ->capture_default_str();
  static const std::map<std::string, SkeletalClass> classes = {
      {"I", SkeletalClass::I}, {"II", SkeletalClass::II}, {"III", SkeletalClass::III}};
  app.add_option_function<std::string>(
         "--class", [options](const std::string& name) { options->skeletal_class = classes.at(name); },
         "skeletal class: I (ANB 2 deg, default), II (ANB ~5) or III (ANB ~-3)")
      ->check(CLI::IsMember({"I", "II", "III"}));
  app.add_option("--patient-id", options->patient_id, "Patient ID of the phantom (another ID: another patient)")
      ->capture_default_str();
  app.callback([options, &ctx] { run_sample(*options, ctx); });
}

}  // namespace maxillo::cli
