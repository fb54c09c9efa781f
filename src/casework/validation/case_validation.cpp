#include "casework/validation/case_validation.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "ceph/landmark_frame.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/parallel_slabs.h"
#include "imaging/segmentation.h"
#include "imaging/volume_assembly.h"
#include "mesh/mesh_io.h"
#include "geometry/mesh_transform.h"
#include "mesh/surface_extraction.h"
#include "imaging/hounsfield_reading.h"
#include "records/archived_series.h"
#include "records/case_landmarks.h"
#include "casework/surfaces/case_surfaces.h"
#include "records/derivation.h"
#include "records/plan_archive.h"
#include "casework/validation/validation_json.h"
#include "casework/validation/validation_views.h"
#include "casework/plan/plan_views.h"
#include "render/anatomical_views.h"
#include "validation/region_statistics.h"
#include "validation/skin_cavities.h"

namespace maxillo::casework {
namespace {

validation::FaceLandmarks face_landmarks(const LandmarkSet& landmarks) {
  const std::string subject = "validation regions";
  auto bilateral = [&](const std::string& label) {
    auto p = bilateral_mean(landmarks, label);
    if (!p) throw Error(ErrorCode::kBadValue, subject, "needs the landmark " + label + " (or its R and L versions)");
    return *p;
  };
  validation::FaceLandmarks l;
  l.subnasale = require_landmark(landmarks, "Sn", subject);
  l.labrale_superius = require_landmark(landmarks, "Ls", subject);
  l.labrale_inferius = require_landmark(landmarks, "Li", subject);
  l.soft_pogonion = require_landmark(landmarks, "PogS", subject);
  l.menton = require_landmark(landmarks, "Me", subject);
  l.orbitale = bilateral("Or");
  l.porion = bilateral("Po");
  return l;
}

validation::FaceAxes face_axes(const LandmarkSet& landmarks) {
  const auto frame = anatomical_frame(landmarks);
  return {frame.anterior, frame.superior, frame.left};
}

// Mean and largest distance between where the planned and the actual move put the surface.
std::pair<double, double> move_difference(const TriangleMesh& surface, const Eigen::Isometry3d& planned,
                                          const Eigen::Isometry3d& actual) {
  double sum = 0, largest = 0;
  for (Eigen::Index v = 0; v < surface.vertex_count(); ++v) {
    const Eigen::Vector3d p = surface.vertices.row(v).transpose();
    const double d = (planned * p - actual * p).norm();
    sum += d;
    largest = std::max(largest, d);
  }
  return {surface.vertex_count() ? sum / double(surface.vertex_count()) : 0.0, largest};
}

// The surface of each moved segment and of the cranium at the CT's bone threshold inside the segment (and along its
// cuts): the same definition of "bone surface" as the post-operative bone it is fitted to. Surfaces of the label mask instead sit up to half a
// voxel off it, which biased the fitted moves by ~0.2 mm.
std::vector<SegmentSurface> segment_bone_surfaces(const PlannedCase& planned) {
  const double bone_hu = SegmentationOptions{}.bone_hu;
  SurfaceOptions options;
  options.keep_largest_components = 0;  // a segment may be several pieces
  options.target_triangles = 80000;
  options.grid = SurfaceGrid::Native;  // the fit's precision: every voxel of the bone's edge
  std::vector<SegmentSurface> surfaces;
  for (const auto& stats : planned.cut.stats)
    if (stats.segment == planning::Segment::kCranium || planned.planned_moves.count(uint8_t(stats.segment)) > 0)
      surfaces.push_back({stats.segment, {}});
  // One segment per thread, each into its own slot.
  for_each_slab(0, int(surfaces.size()),
                [&](int first, int last) {
                  for (int s = first; s < last; ++s) {
                    auto& surface = surfaces[size_t(s)];
                    const uint8_t label = uint8_t(surface.segment);
                    surface.mesh = extract_region_surface(planned.preop_ct, planned.cut.segments, {label, label},
                                                          bone_hu, options);
                  }
                },
                {.min_slab_size = 1});
  return surfaces;
}

// Step 2: each moved segment onto the post-operative bone, from its planned move.
std::vector<SegmentOutcome> actual_segment_moves(const PlannedCase& planned,
                                                 const std::vector<SegmentSurface>& surfaces,
                                                 const TriangleMesh& postop_bone, const validation::IcpOptions& icp) {
  std::vector<SegmentOutcome> outcomes;
  for (const auto& [segment, move] : planned.planned_moves) {
    auto surface =
        std::find_if(surfaces.begin(), surfaces.end(), [&](const auto& s) { return uint8_t(s.segment) == segment; });
    if (surface == surfaces.end()) continue;
    const auto fit = validation::rigid_icp(surface->mesh, postop_bone, move, icp);
    SegmentOutcome outcome{segment, move, fit.transform, fit.rms_mm};
    std::tie(outcome.mean_difference_mm, outcome.max_difference_mm) =
        move_difference(surface->mesh, move, fit.transform);
    log::info("segment ", planning::segment_name(planning::Segment(segment)), ": actual move differs from the plan by ",
              outcome.mean_difference_mm, " mm on average (ICP rms ", fit.rms_mm, " mm)");
    outcomes.push_back(outcome);
  }
  return outcomes;
}

double cranium_residual(const std::vector<SegmentSurface>& surfaces, const TriangleMesh& postop_bone,
                        const validation::IcpOptions& icp) {
  for (const auto& s : surfaces)
    if (s.segment == planning::Segment::kCranium)
      return validation::rigid_icp(s.mesh, postop_bone, Eigen::Isometry3d::Identity(), icp).rms_mm;
  return std::numeric_limits<double>::quiet_NaN();
}

// Step 4b: the corresponding-point distances as a map over every predicted vertex.
std::vector<double> corresponding_map(const TriangleMesh& predicted, const TriangleMesh& actual,
                                      const std::vector<bool>& face, const validation::CpdOptions& options) {
  const auto values = validation::corresponding_point_distances(predicted, actual, face, options);
  std::vector<double> map(face.size(), std::numeric_limits<double>::quiet_NaN());
  size_t next = 0;
  for (size_t v = 0; v < face.size() && next < values.size(); ++v)
    if (face[v]) map[v] = values[next++];
  return map;
}

std::vector<RegionStatistics> region_statistics(const CaseValidation& v, double tolerance_mm) {
  std::vector<RegionStatistics> rows;
  for (const auto& closest : validation::statistics_by_region(v.closest_mm, v.regions, tolerance_mm))
    rows.push_back({closest.region, closest.statistics, {}});
  if (!v.corresponding_mm.empty()) {
    const auto corresponding = validation::statistics_by_region(v.corresponding_mm, v.regions, tolerance_mm);
    for (size_t i = 0; i < rows.size(); ++i) rows[i].corresponding = corresponding[i].statistics;
  }
  return rows;
}

void write_skins(const CaseValidation& v, const std::filesystem::path& out) {
  auto column = [](const std::vector<double>& values) {
    return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
  };
  std::vector<PointArray> arrays{{"closest_point_distance", column(v.closest_mm)}};
  if (!v.corresponding_mm.empty()) arrays.push_back({"corresponding_point_distance", column(v.corresponding_mm)});
  write_mesh(v.predicted_skin, out / "predicted-skin.vtp", arrays);
  write_mesh(v.actual_skin, out / "actual-skin.vtp");
}

}  // namespace

std::vector<validation::FaceRegion> face_regions_of(const TriangleMesh& preop_skin, const LandmarkSet& landmarks,
                                                    const validation::FaceRegionOptions& options) {
  auto regions =
      validation::classify_face_regions(preop_skin.vertices, face_landmarks(landmarks), face_axes(landmarks), options);
  // The outer face only: the skin lining the mouth's slit and the nostrils is left out.
  const auto cavity =
      validation::cavity_vertices(preop_skin, validation::region_mask(regions, validation::FaceRegion::kOutside));
  for (size_t i = 0; i < regions.size(); ++i)
    if (cavity[i]) regions[i] = validation::FaceRegion::kOutside;
  return regions;
}

Json ValidationOptions::to_json() const {
  return Json{{"registration",
               {{"levels", registration.levels},
                {"bins", registration.histogram_bins},
                {"sampling", registration.sampling_fraction},
                {"seed", registration.seed}}},
              {"icp", {{"max_pair_mm", icp.max_pair_distance_mm}, {"samples", icp.max_samples}}},
              {"soft_tissue",
               {{"model", model_name(soft_tissue.model)},
                {"poisson", soft_tissue.poisson_ratio},
                {"max_tets", soft_tissue.meshing.max_tets}}},
              {"correspondence", corresponding_points ? Json{{"beta", correspondence.beta_mm},
                                                             {"lambda", correspondence.lambda},
                                                             {"w", correspondence.outlier_weight}}
                                                      : Json(nullptr)},
              {"tolerance_mm", tolerance_mm}};
}

std::optional<int64_t> postop_series(const CaseContents& contents) {
  std::optional<int64_t> newest;
  for (const auto& entry : contents.series)
    if (entry.role == "postop") newest = entry.series.id;  // series come by study date
  return newest;
}

namespace {

// What a case's validation inputs hash is made of, but for the series' contents (read for all cases at once).
struct InputsOfCase {
  int64_t preop_series = 0, postop_series = 0;
  std::string plan_sha256, landmarks_hash;
};

// Nothing when the case lacks a post-operative CT, a plan or landmarks (checked before the pre-operative CT, whose
// absence throws). Reads the landmarks object.
std::optional<InputsOfCase> inputs_of_case(const Archive& archive, const CaseContents& contents,
                                           const std::vector<ArtefactRecord>& artefacts) {
  const auto post = postop_series(contents);
  const auto plan = records::latest_plan_sha256(artefacts);
  const auto landmarks = records::latest_landmarks(archive, artefacts);
  if (!post || !plan || landmarks.empty()) return std::nullopt;
  return InputsOfCase{records::primary_series(contents), *post, *plan, landmarks_hash(landmarks)};
}

}  // namespace

std::map<int64_t, CaseInputsHash> validation_inputs_hashes(const Archive& archive, const std::vector<int64_t>& case_ids,
                                                           const ValidationOptions& options) {
  const auto contents = archive.case_contents(case_ids);
  auto artefacts = archive.artefacts(case_ids);
  std::map<int64_t, CaseInputsHash> result;
  std::map<int64_t, InputsOfCase> eligible;
  for (int64_t id : case_ids) {
    auto& entry = result[id];
    entry.artefacts = std::move(artefacts[id]);
    try {  // a case whose records cannot be read fails alone
      const auto found = contents.find(id);
      if (found == contents.end()) throw Error(ErrorCode::kNotFound, std::to_string(id), "no such case");
      if (auto inputs = inputs_of_case(archive, found->second, entry.artefacts)) eligible[id] = std::move(*inputs);
    } catch (...) {
      entry.error = std::current_exception();
    }
  }
  std::vector<int64_t> series;
  for (const auto& [id, inputs] : eligible) series.insert(series.end(), {inputs.preop_series, inputs.postop_series});
  const auto series_hashes = records::series_content_hashes(archive, series);  // in the order asked
  const Json parameters = options.to_json();
  size_t next = 0;
  for (const auto& [id, inputs] : eligible) {
    result[id].hash = records::derivation_key(
        {series_hashes[next], series_hashes[next + 1], inputs.plan_sha256, inputs.landmarks_hash}, parameters);
    next += 2;
  }
  return result;
}

std::optional<std::string> validation_inputs_hash(const Archive& archive, int64_t case_id,
                                                  const ValidationOptions& options) {
  auto found = validation_inputs_hashes(archive, {case_id}, options).at(case_id);
  if (found.error) std::rethrow_exception(found.error);
  return found.hash;
}

CaseValidation validate_case(Archive& archive, int64_t case_id, const ValidationOptions& options,
                             const std::filesystem::path& out, const PlannedCase* given) {
  const auto started = std::chrono::steady_clock::now();
  const std::string subject = "case:" + std::to_string(case_id);
  CaseValidation v;
  v.case_id = case_id;
  const auto contents = archive.case_contents(case_id);
  const auto hash = validation_inputs_hash(archive, case_id, options);
  const auto post = postop_series(contents);
  if (!post)
    throw Error(ErrorCode::kNotFound, subject, "the case has no post-operative CT (a series with role postop)");
  if (!hash) throw Error(ErrorCode::kNotFound, subject, "the case needs a plan and landmarks to be validated");
  v.inputs_hash = *hash;
  v.postop_series = *post;

  const PlannedCase loaded = given ? PlannedCase{} : load_planned_case(archive, case_id);
  const PlannedCase& planned = given ? *given : loaded;
  v.preop_series = planned.preop_series;

  log::info("validation: registering the post-operative CT, its surfaces and the pre-operative bone segments");
  const Volume postop_ct = as_hounsfield_units(records::load_archived_series(archive, v.postop_series));
  RigidRegistrationOptions registration = options.registration;
  if (!registration.box) registration.box = cranial_registration_box(planned.preop_ct, &planned.landmarks);
  std::optional<CaseSurfaces> postop = stored_case_surfaces(archive, case_id, v.postop_series);
  const bool extract_postop = !postop;
  if (extract_postop) postop.emplace();
  std::vector<SegmentSurface> surfaces;
  // The post-operative surfaces (4 s on the demo) are extracted beside the registration and the pre-operative bone
  // segments (1.7 + 3.5 s): each reads only the loaded CTs and writes only its own result, and the archive stays on
  // this thread. (All three at once were no faster on two cores and raised the demo's peak memory by 0.1 GB more.)
  run_concurrently({[&] {
                      v.registration = register_rigid(planned.preop_ct, postop_ct, registration);
                      surfaces = segment_bone_surfaces(planned);
                    },
                    [&] {
                      if (extract_postop) *postop = extract_case_surfaces(postop_ct);
                    }});
  if (extract_postop) store_case_surfaces(archive, case_id, v.postop_series, *postop);

  log::info("validation: the bone moves as performed");
  const TriangleMesh postop_bone = transformed(postop->bone, v.registration.moving_to_fixed);
  v.actual_skin = transformed(postop->skin, v.registration.moving_to_fixed);
  v.segments = actual_segment_moves(planned, surfaces, postop_bone, options.icp);
  v.cranium_icp_rms_mm = cranium_residual(surfaces, postop_bone, options.icp);

  log::info("validation: predicting the face for the actual moves");
  SegmentMoves actual;
  for (const auto& s : v.segments) actual[s.segment] = s.actual;
  const SoftTissueInput input{&planned.tissues.jaws, &planned.cut.segments, &planned.skin, planned.landmarks, actual};
  v.predicted_skin =
      predict_soft_tissue(input, options.soft_tissue, planned.face_model(options.soft_tissue).get()).skin_after;

  log::info("validation: predicted against post-operative skin");
  v.regions = face_regions_of(planned.skin, planned.landmarks, options.regions);
  const auto face = validation::region_mask(v.regions, validation::FaceRegion::kOutside);
  std::filesystem::create_directories(out);
  const auto frame = anatomical_frame(planned.landmarks);
  // The corresponding points (coherent point drift, the longest step here) need nothing the closest-point map and
  // its views make: they run beside them, each writing only its own member; rendering stays on this thread.
  run_concurrently(
      {[&] {
         v.closest_mm = validation::signed_distance_map(v.predicted_skin, v.actual_skin, face);
         v.error_maps = render_error_maps(v.predicted_skin, v.closest_mm, frame, options.error_map_range_mm, out);
         v.profile_png = out / "profile.png";
         write_profile_overlay(planned.skin, v.predicted_skin, v.actual_skin, planned.landmarks, frame, v.profile_png);
       },
       [&] {
         if (options.corresponding_points)
           v.corresponding_mm = corresponding_map(v.predicted_skin, v.actual_skin, face, options.correspondence);
       }});
  v.statistics = region_statistics(v, options.tolerance_mm);
  write_skins(v, out);
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  v.summary = validation_json(v, contents);
  write_file_atomically(out / "validation.json", v.summary.dump(2) + "\n");
  return v;
}

}  // namespace maxillo::casework
