// maxillo register FIXED MOVING [--box xmin,ymin,zmin,xmax,ymax,zmax] [--out T.json]:
// rigid registration of a post-operative CT (MOVING) to the pre-operative CT (FIXED) by mutual
// information on an unaltered subvolume (imaging/rigid_registration.h).
// FIXED and MOVING are each a DICOM folder or an archived series (archive id or Series Instance
// UID). The default box is the cranium above the infraorbital rim: from the orbitale landmarks of
// the fixed series' case when it is archived and its case has 3D landmarks, else the top of the
// head in the fixed CT.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "archive/archive.h"
#include "cli/command.h"
#include "cli/folder_files.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json.h"
#include "imaging/rigid_registration.h"
#include "imaging/volume_assembly.h"
#include "occlusion/occlusion_files.h"
#include "records/archived_series.h"
#include "records/case_landmarks.h"

namespace maxillo::cli {
namespace {

struct RegisterOptions {
  std::string fixed, moving;
  std::vector<double> box;  // 6 numbers or empty
  std::filesystem::path out;
};

// A CT to register and where it came from.
struct LoadedSeries {
  Volume volume;
  Json source;                    // {"folder": ...} or {"series": id, "series_uid": ...}
  std::optional<int64_t> series;  // archive id when archived
};

// The archive is opened only when an argument is not a folder (two folders need no archive).
class LazyArchive {
 public:
  explicit LazyArchive(std::filesystem::path folder) : folder_(std::move(folder)) {}
  Archive& get() {
    if (!archive_) archive_ = Archive::open(folder_);
    return *archive_;
  }

 private:
  std::filesystem::path folder_;
  std::optional<Archive> archive_;
};

LoadedSeries load_input(const std::string& text, LazyArchive& archive) {
  LoadedSeries loaded;
  if (std::filesystem::is_directory(text)) {
    loaded.volume = load_series_volume(files_below(text));
    loaded.source = {{"folder", text}};
    return loaded;
  }
  Archive& a = archive.get();
  const int64_t series = a.resolve_series(text);
  loaded.volume = records::load_archived_series(a, series);
  loaded.series = series;
  loaded.source = {{"series", series}, {"series_uid", a.series_by_id(series)->series_uid}};
  return loaded;
}

// The case holding the series (a patient may have several): the one listing it, else the
// patient's default case.
std::optional<int64_t> case_of_series(const Archive& archive, int64_t series) {
  const auto record = archive.series_by_id(series);
  const auto study = record ? archive.study(record->study) : std::nullopt;
  if (!study) return std::nullopt;
  for (const CaseRecord& c : archive.cases()) {
    if (c.patient != study->patient) continue;
    for (const CaseSeries& s : archive.case_contents(c.id).series)
      if (s.series.id == series) return c.id;
  }
  if (auto c = archive.case_of_patient(study->patient)) return c->id;
  return std::nullopt;
}

// The newest 3D (volume LPS) landmark set of the series' case; 2D cephalogram sets do not count.
std::optional<LandmarkSet> case_landmarks_of(const Archive& archive, int64_t series) {
  const auto case_id = case_of_series(archive, series);
  if (!case_id) return std::nullopt;
  const auto history = records::landmark_history(archive, *case_id);
  for (auto it = history.rbegin(); it != history.rend(); ++it)
    if (it->frame.geometry == LandmarkGeometry::kVolumeLps && !it->landmarks.empty()) return it->landmarks;
  return std::nullopt;
}

Json box_json(const RegistrationBox& box, const std::string& source) {
  return {{"min", {box.min.x(), box.min.y(), box.min.z()}},
          {"max", {box.max.x(), box.max.y(), box.max.z()}},
          {"source", source}};
}

void print_text(const RigidRegistrationResult& result, const std::string& box_source, const RegistrationBox& box,
                const std::filesystem::path& out) {
  const Eigen::Isometry3d& t = result.moving_to_fixed;
  const double angle_deg = Eigen::AngleAxisd(t.linear()).angle() * 180.0 / 3.14159265358979323846;
  std::printf("registered in %.2f s, %d iterations, metric %.5f\n", result.seconds, result.iterations, result.metric);
  std::printf("moving -> fixed: rotation %.3f deg, translation (%.3f, %.3f, %.3f) mm (LPS)\n", angle_deg,
              t.translation().x(), t.translation().y(), t.translation().z());
  std::printf("box (%s): z %.1f .. %.1f mm\n", box_source.c_str(), box.min.z(), box.max.z());
  if (!out.empty()) std::printf("-> %s\n", out.string().c_str());
}

void run_register(const RegisterOptions& options, CommandContext& ctx) {
  LazyArchive archive(resolve_archive_dir(ctx.global));
  const LoadedSeries fixed = load_input(options.fixed, archive);
  const LoadedSeries moving = load_input(options.moving, archive);

  RigidRegistrationOptions registration;
  std::string box_source = "--box";
  if (options.box.size() == 6) {
    registration.box = RegistrationBox{{options.box[0], options.box[1], options.box[2]},
                                       {options.box[3], options.box[4], options.box[5]}};
  } else {
    const std::optional<LandmarkSet> landmarks =
        fixed.series ? case_landmarks_of(archive.get(), *fixed.series) : std::nullopt;
    registration.box = cranial_registration_box(fixed.volume, landmarks ? &*landmarks : nullptr);
    const bool from_orbitale = landmarks && (bilateral_mean(*landmarks, "Or") || find_landmark(*landmarks, "Or_R") ||
                                             find_landmark(*landmarks, "Or_L"));
    box_source = from_orbitale ? "above orbitale (case landmarks)" : "top of the head (no orbitale landmarks)";
  }

  const RigidRegistrationResult result = register_rigid(fixed.volume, moving.volume, registration);
  Json json = {{"moving_to_fixed", occlusion::transform_to_json(result.moving_to_fixed)},
               {"frame", "patient LPS, mm: p_fixed = M * p_moving"},
               {"metric", result.metric},
               {"iterations", result.iterations},
               {"seconds", result.seconds},
               {"box", box_json(*registration.box, box_source)},
               {"fixed", fixed.source},
               {"moving", moving.source}};
  if (!options.out.empty()) write_file_atomically(options.out, json.dump(2) + "\n");
  if (ctx.global.json) {
    std::cout << json.dump(2) << "\n";
    return;
  }
  print_text(result, box_source, *registration.box, options.out);
}

}  // namespace

void attach_register(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<RegisterOptions>();
  app.add_option("fixed", options->fixed, "pre-operative CT: DICOM folder, archive series id or Series Instance UID")
      ->required();
  app.add_option("moving", options->moving, "post-operative CT: DICOM folder, archive series id or Series Instance UID")
      ->required();
  app.add_option("--box", options->box,
                 "metric subvolume in the fixed CT, LPS mm: xmin,ymin,zmin,xmax,ymax,zmax "
                 "(default: the cranium above the infraorbital rim)")
      ->delimiter(',')
      ->expected(6)
      ->check(kCoordinateMm);
  app.add_option("--out", options->out, "write the transform as JSON (moving_to_fixed 4x4, metric, box)");
  app.callback([options, &ctx] { run_register(*options, ctx); });
}

}  // namespace maxillo::cli
