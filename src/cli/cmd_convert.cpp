// maxillo convert VOLUME --out DIR: a MetaImage/NRRD volume -> a DICOM CT series.
// Research volumes often lack a trustworthy frame; --direction/--origin place them in patient
// LPS and --hu-offset turns stored values into HU, so that the series reads back as a proper CT.
#include <cmath>
#include <iostream>

#include <Eigen/LU>  // determinant()

#include "cli/command.h"
#include "core/error.h"
#include "core/json.h"
#include "core/log.h"
#include "dicom/dicom_series_writer.h"
#include "imaging/head_orientation.h"
#include "imaging/volume_file.h"

namespace maxillo::cli {
namespace {

struct ConvertOptions {
  std::filesystem::path input;
  std::filesystem::path out;
  std::vector<double> direction;  // 9 numbers: i axis, j axis, k axis (each x,y,z in LPS)
  std::vector<double> origin;     // 3 numbers: LPS mm of voxel (0,0,0)
  double hu_offset = 0;
  std::string patient_name = "Anonymous";
  std::string patient_id = "ANONYMOUS";
  std::string series_description = "converted volume";
};

Eigen::Matrix3d checked_direction(const std::vector<double>& numbers) {
  Eigen::Matrix3d direction;
  for (int axis = 0; axis < 3; ++axis)
    for (int c = 0; c < 3; ++c) direction(c, axis) = numbers[size_t(3 * axis + c)];
  const double error = (direction.transpose() * direction - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (error > 1e-3)
    throw Error(ErrorCode::kUsage, "--direction",
                "the three axes must be orthogonal unit vectors (|D^T D - I| = " + std::to_string(error) + ")");
  if (direction.determinant() < 0)
    log::info("--direction is left-handed: slices will be written in decreasing order along their normal");
  return direction;
}

void run_convert(const ConvertOptions& options, CommandContext& ctx) {
  Volume volume = read_volume_file(options.input, {.hu_offset = options.hu_offset});
  VolumeGeometry& g = volume.geometry;
  if (!options.direction.empty()) g.direction = checked_direction(options.direction);
  if (!options.origin.empty()) g.origin = {options.origin[0], options.origin[1], options.origin[2]};
  if (g.size.x() > 65535 || g.size.y() > 65535)
    throw Error(ErrorCode::kBadValue, options.input.string(), "slices larger than 65535 pixels cannot be DICOM");

  SeriesMetadata metadata;
  metadata.patient_name = options.patient_name;
  metadata.patient_id = options.patient_id;
  metadata.series_description = options.series_description;
  log::debug("convert: patient '", options.patient_name, "' id '", options.patient_id, "'");
  const WrittenSeries written = write_ct_series(volume, metadata, options.out);
  // The header this conversion gave the volume, checked against the anatomy: a wrong
  // --direction or a missing --hu-offset is said now, not discovered when planning refuses.
  const HeadOrientation orientation = check_head_orientation(volume);
  if (orientation.contradicts_header()) log::warning(options.input.string(), ": ", orientation.finding());

  Json result = {{"input", options.input.string()},
                 {"folder", options.out.string()},
                 {"files", written.files.size()},
                 {"study_instance_uid", written.study_instance_uid},
                 {"series_instance_uid", written.series_instance_uid},
                 {"size", {g.size.x(), g.size.y(), g.size.z()}},
                 {"spacing_mm", {g.spacing.x(), g.spacing.y(), g.spacing.z()}},
                 {"origin_lps_mm", {g.origin.x(), g.origin.y(), g.origin.z()}},
                 {"orientation",
                  {{"contradicts_header", orientation.contradicts_header()},
                   {"finding", orientation.finding()},
                   {"grey_values", orientation.grey.describe()}}}};
  if (ctx.global.json) {
    std::cout << result.dump(2) << "\n";
    return;
  }
  std::cout << "wrote " << written.files.size() << " CT slices of " << g.size.x() << " x " << g.size.y() << " ("
            << g.spacing.x() << " x " << g.spacing.y() << " x " << g.spacing.z() << " mm) to " << options.out.string()
            << "\nseries " << written.series_instance_uid << "\norientation: " << orientation.finding()
            << "\ngrey values: " << orientation.grey.describe() << "\n";
}

}  // namespace

void attach_convert(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<ConvertOptions>();
  app.add_option("volume", options->input, "MetaImage (.mhd/.mha) or NRRD (.nrrd/.nhdr) volume")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--out", options->out, "folder for the DICOM series (created if needed)")->required();
  app.add_option("--direction", options->direction,
                 "9 numbers: the i, j and k axes as LPS unit vectors (overrides the file's)")
      ->expected(9)
      ->delimiter(',')
      ->check(CLI::Range(-1.0, 1.0));
  app.add_option("--origin", options->origin, "x,y,z: LPS position of voxel (0,0,0) in mm (overrides the file's)")
      ->expected(3)
      ->delimiter(',')
      ->check(kCoordinateMm);
  app.add_option("--hu-offset", options->hu_offset, "added to every stored value to give HU (e.g. -1024)")
      ->check(CLI::Range(-32768.0, 32767.0))
      ->capture_default_str();
  app.add_option("--patient-name", options->patient_name, "DICOM patient name (Family^Given)")->capture_default_str();
  app.add_option("--patient-id", options->patient_id, "DICOM patient ID")->capture_default_str();
  app.add_option("--series-description", options->series_description, "DICOM series description")
      ->capture_default_str();
  app.callback([options, &ctx] { run_convert(*options, ctx); });
}

}  // namespace maxillo::cli
