// maxillo sample --out DIR [--spacing MM] [--class I|II|III] [--patient-id ID] [--vary] [--cbct]: writes the
// synthetic craniofacial phantom as a DICOM CT series (DIR/ct/) with its analytic landmarks
// (DIR/landmarks.mrk.json, DIR/landmarks.csv; LPS mm). The repository ships no DICOM: this
// regenerates it in seconds. --vary draws the anatomy, pose and noise from the Patient ID (another
// patient per ID); --cbct gives the scan a cone-beam scanner's grey values, cupping, metal streaks
// and cut field.
// The work is pipeline::write_sample_case (shared with `maxillo demo`).
#include <iostream>
#include <map>

#include "cli/command.h"
#include "core/json.h"
#include "casework/sample/sample_case.h"
#include "sample/phantom_variation.h"

namespace maxillo::cli {
namespace {

struct SampleOptions {
  std::filesystem::path out;
  casework::SampleRequest request;
};

void run_sample(const SampleOptions& options, CommandContext& ctx) {
  const casework::SampleRequest& request = options.request;
  const casework::SampleCase sample = casework::write_sample_case(request, options.out);
  const PhantomSpec& spec = sample.spec;
  const VolumeGeometry& g = sample.geometry;
  const std::string class_name(request.varied ? "varied" : casework::name_of(request.skeletal_class));
  if (ctx.global.json) {
    Json result = {{"folder", options.out.string()},
                   {"skeletal_class", class_name},
                   {"series_description", request.series_description()},
                   {"variation", request.varied ? describe_variation(spec) : ""},
                   {"maxillary_advancement_mm", spec.maxillary_advancement_mm},
                   {"mandibular_protrusion_mm", spec.mandibular_protrusion_mm},
                   {"mandibular_deviation_mm", spec.mandibular_deviation_mm},
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
  std::cout << "wrote " << sample.series.files.size() << " slices of " << g.size.x() << " x " << g.size.y() << " ("
            << request.series_description() << ") to " << sample.ct_folder.string() << "\n";
  if (request.varied) std::cout << "drawn from the Patient ID: " << describe_variation(spec) << "\n";
  std::cout << "wrote " << sample.landmarks.size() << " landmarks (LPS mm) to " << sample.markups_file.string()
            << " and " << sample.csv_file.string() << "\n";
}

}  // namespace

void attach_sample(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<SampleOptions>();
  app.add_option("--out", options->out, "output folder (created): ct/, landmarks.mrk.json, landmarks.csv")->required();
  app.add_option("--spacing", options->request.spacing_mm, "isotropic voxel spacing in mm (0.25 to 4)")
      ->check(CLI::Range(0.25, 4.0))
      ->capture_default_str();
  static const std::map<std::string, SkeletalClass> classes = {
      {"I", SkeletalClass::I}, {"II", SkeletalClass::II}, {"III", SkeletalClass::III}};
  app.add_option_function<std::string>(
         "--class", [options](const std::string& name) { options->request.skeletal_class = classes.at(name); },
         "skeletal class: I (ANB 2 deg, default), II (ANB ~5) or III (ANB ~-3)")
      ->check(CLI::IsMember({"I", "II", "III"}));
  app.add_option("--patient-id", options->request.patient_id, "Patient ID of the phantom")->capture_default_str();
  app.add_flag(
      "--vary", options->request.varied,
      "draw the anatomy (size, jaws), the pose and the noise from the Patient ID: another ID, another patient");
  app.add_flag("--cbct", options->request.cone_beam,
               "a cone-beam scan: grey values that are not HU, cupping, metal streaks, a cut field of view");
  app.callback([options, &ctx] { run_sample(*options, ctx); });
}

}  // namespace maxillo::cli
