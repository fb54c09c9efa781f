// maxillo surfaces INPUT... --out DIR: one DICOM series -> skin and bone surfaces.
// Series -> volume (imaging/volume_assembly) -> tissue labels (imaging/segmentation) ->
// iso-surfaces of the labelled regions (mesh/surface_extraction) -> DIR/skin.<fmt>, DIR/bone.<fmt>.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>

#include "cli/command.h"
#include "core/error.h"
#include "core/json.h"
#include "imaging/hounsfield_reading.h"
#include "imaging/segmentation.h"
#include "imaging/volume_assembly.h"
#include "mesh/mesh_io.h"
#include "geometry/mesh_measures.h"
#include "mesh/surface_extraction.h"

namespace maxillo::cli {
namespace {

struct SurfacesOptions {
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path out;
  double skin_hu = -400;
  double bone_hu = 300;
  int64_t triangles = 200000;
  int smoothing_iterations = 15;
  double headrest_gap_mm = 3;
  std::string bone_edge = "threshold";  // or "half-maximum" (segmentation.h)
  std::string format = "stl";
};

class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Files given directly, and every regular file below the folders given (sorted, DICOMDIR and
// hidden files skipped).
std::vector<std::filesystem::path> series_files(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::filesystem::path> files;
  for (const auto& input : inputs) {
    if (!std::filesystem::is_directory(input)) {
      files.push_back(input);
      continue;
    }
    std::vector<std::filesystem::path> found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(input)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && name != "DICOMDIR" && !name.starts_with(".")) found.push_back(entry.path());
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  if (files.empty()) throw Error(ErrorCode::kFileNotFound, inputs.front().string(), "no files in the input folders");
  return files;
}

Json describe_surface(const std::string& name, const TriangleMesh& mesh, const std::filesystem::path& file,
                      double seconds) {
  Components components = connected_components(mesh);
  return {{"name", name},
          {"file", file.string()},
          {"vertices", mesh.vertex_count()},
          {"triangles", mesh.face_count()},
          {"components", components.face_counts.size()},
          {"area_mm2", surface_area(mesh)},
          {"volume_mm3", signed_volume(mesh)},
          {"watertight", is_watertight(mesh)},
          {"seconds", seconds}};
}

Json make_surface(const std::string& name, const Volume& volume, const LabelVolume& labels, LabelRange region,
                  double iso_hu, const SurfaceOptions& surface_options, const SurfacesOptions& options) {
  Stopwatch clock;
  TriangleMesh mesh = extract_region_surface(volume, labels, region, iso_hu, surface_options);
  if (mesh.face_count() == 0)
    throw Error(ErrorCode::kEmptyResult, name, "no " + name + " surface at " + std::to_string(int(iso_hu)) + " HU");
  const std::filesystem::path file = options.out / (name + "." + options.format);
  write_mesh(mesh, file);
  return describe_surface(name, mesh, file, clock.seconds());
}

// How the scan's values were read, and the grey values of the scan the thresholds fell on.
Json grey_values_json(const GreyReading& reading, const SurfacesOptions& options) {
  return {{"hounsfield_as_stored", reading.hounsfield_as_stored()},
          {"reading", reading.describe()},
          {"cupping_undone", reading.cupping_depth},
          {"skin_threshold_grey", reading.grey_of(options.skin_hu)},
          {"bone_threshold_grey", reading.grey_of(options.bone_hu)}};
}

void print_surfaces_text(const Json& result) {
  const Json& v = result["volume"];
  std::cout << "volume: " << v["size"][0] << " x " << v["size"][1] << " x " << v["size"][2] << " voxels, spacing "
            << v["spacing_mm"][0] << " x " << v["spacing_mm"][1] << " x " << v["spacing_mm"][2] << " mm ("
            << v["slice_spacing"].get<std::string>() << "), loaded in " << v["seconds"] << " s\n";
  const Json& grey = result["grey_values"];
  std::cout << "grey values: " << grey["reading"].get<std::string>();
  if (!grey["hounsfield_as_stored"].get<bool>())
    std::cout << "; thresholds at " << std::lround(grey["skin_threshold_grey"].get<double>()) << " (skin) and "
              << std::lround(grey["bone_threshold_grey"].get<double>()) << " (bone) in the scan's values";
  std::cout << "\n";
  std::cout << "segmentation: " << result["segmentation_seconds"] << " s\n";
  for (const Json& s : result["surfaces"])
    std::cout << s["name"].get<std::string>() << ": " << s["triangles"] << " triangles, " << s["components"]
              << " component(s), area " << s["area_mm2"].get<double>() / 100 << " cm2, enclosed volume "
              << s["volume_mm3"].get<double>() / 1000 << " cm3 (patient LPS), " << s["seconds"] << " s -> "
              << s["file"].get<std::string>() << "\n";
}

void run_surfaces(const SurfacesOptions& options, CommandContext& ctx) {
  Stopwatch total;
  AssemblyReport assembly;
  Stopwatch load_clock;
  // The thresholds are in HU: a cone-beam scan is read as HU first, and the output says how.
  GreyReading reading;
  const Volume volume = as_hounsfield_units(load_series_volume(series_files(options.inputs), &assembly), &reading);
  const double load_seconds = load_clock.seconds();
  const VolumeGeometry& g = volume.geometry;

  Stopwatch segmentation_clock;
  SegmentationOptions segmentation{.skin_hu = options.skin_hu,
                                   .bone_hu = options.bone_hu,
                                   .headrest_gap_mm = options.headrest_gap_mm,
                                   .bone_edge_at_half_maximum = options.bone_edge == "half-maximum"};
  const LabelVolume labels = segment_tissues(volume, segmentation);
  const double segmentation_seconds = segmentation_clock.seconds();

  std::error_code error;
  std::filesystem::create_directories(options.out, error);
  if (error) throw Error(ErrorCode::kWriteFailed, options.out.string(), error.message());
  SurfaceOptions skin{.keep_largest_components = 1,
                      .smoothing_iterations = options.smoothing_iterations,
                      .target_triangles = options.triangles};
  SurfaceOptions bone{.keep_largest_components = 0,
                      .min_component_fraction = 0.001,
                      .smoothing_iterations = options.smoothing_iterations,
                      .target_triangles = options.triangles};
  Json result = {{"volume",
                  {{"size", {g.size.x(), g.size.y(), g.size.z()}},
                   {"spacing_mm", {g.spacing.x(), g.spacing.y(), g.spacing.z()}},
                   {"slices_read", assembly.input_slices},
                   {"slice_spacing", assembly.spacing == SliceSpacing::Uniform ? "uniform" : "resampled"},
                   {"seconds", load_seconds}}},
                 {"grey_values", grey_values_json(reading, options)},
                 {"frame", "patient LPS; lengths mm, areas mm2, volumes mm3"},
                 {"segmentation_seconds", segmentation_seconds},
                 {"surfaces", Json::array()}};
  result["surfaces"].push_back(
      make_surface("skin", volume, labels, {kSoftTissue, kTeeth}, options.skin_hu, skin, options));
  result["surfaces"].push_back(make_surface("bone", volume, labels, {kBone, kTeeth}, options.bone_hu, bone, options));
  result["seconds"] = total.seconds();
  if (ctx.global.json)
    std::cout << result.dump(2) << "\n";
  else
    print_surfaces_text(result);
}

}  // namespace

void attach_surfaces(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<SurfacesOptions>();
  app.add_option("inputs", options->inputs, "DICOM files or folders of ONE series")
      ->required()
      ->check(CLI::ExistingPath);
  app.add_option("--out", options->out, "output folder (created if needed)")->required();
  app.add_option("--skin-hu", options->skin_hu, "skin iso-value, HU")
      ->capture_default_str()
      ->check(CLI::Range(-1000.0, 200.0));
  app.add_option("--bone-hu", options->bone_hu, "bone iso-value, HU")
      ->capture_default_str()
      ->check(CLI::Range(100.0, 1500.0));
  app.add_option("--triangles", options->triangles, "target triangle count per surface (0: no decimation)")
      ->capture_default_str()
      ->check(CLI::Range(int64_t(0), int64_t(100000000)));
  app.add_option("--smoothing", options->smoothing_iterations, "windowed-sinc smoothing iterations (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 500));
  app.add_option("--headrest-gap", options->headrest_gap_mm,
                 "opening radius (mm) that detaches a head rest touching the skin (0: off)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 20.0));
  app.add_option("--bone-edge", options->bone_edge,
                 "where bone ends: the threshold's boundary, or trimmed by the half-maximum rule (the partial-volume "
                 "voxel over each bone left out)")
      ->capture_default_str()
      ->check(CLI::IsMember({"threshold", "half-maximum"}));
  app.add_option("--format", options->format, "mesh file format")
      ->capture_default_str()
      ->check(CLI::IsMember({"stl", "ply", "obj", "vtp"}));
  app.callback([options, &ctx] { run_surfaces(*options, ctx); });
}

}  // namespace maxillo::cli
