#include "casework/surfaces/case_surfaces.h"

#include <chrono>

#include "archive/artefact_kind.h"
#include "core/log.h"
#include "core/parallel_slabs.h"
#include "imaging/hounsfield_reading.h"
#include "imaging/volume_assembly.h"
#include "records/archived_series.h"
#include "records/derivation.h"
#include "records/mesh_artefact.h"

namespace maxillo::casework {
namespace {

const std::string kSkinKind = kind_name(ArtefactKind::kSurfaceSkin);
const std::string kBoneKind = kind_name(ArtefactKind::kSurfaceBone);

Json surface_json(const SurfaceOptions& o) {
  return {{"keep_largest_components", o.keep_largest_components},
          {"min_component_fraction", o.min_component_fraction},
          {"smoothing_iterations", o.smoothing_iterations},
          {"smoothing_passband", o.smoothing_passband},
          {"target_triangles", o.target_triangles},
          {"grid", o.grid == SurfaceGrid::Native ? "native" : "for-budget"}};
}

// The derivation key of a series' surfaces: its content and every parameter of the recipe.
std::string surfaces_key(Archive& archive, int64_t series, const Json& parameters) {
  return records::derivation_key({records::series_content_hash(archive, series)}, parameters);
}

}  // namespace

// Skin: the body mask's boundary (head rest and table removed by the segmentation), drawn
// through the CT's own sub-voxel values. Bone: all bone including teeth.
CaseSurfaces extract_case_surfaces(const Volume& scan, const SurfaceRecipe& recipe, SurfaceTimes* times,
                                   const LabelVolume* segmented) {
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  SurfaceTimes spent;
  const auto started = Clock::now();
  // The thresholds are in HU: a cone-beam scan is read as HU first (hounsfield_reading.h).
  const std::optional<Volume> converted = in_hounsfield_units(scan);
  const Volume& volume = converted ? *converted : scan;
  const LabelVolume made = segmented ? LabelVolume{} : segment_tissues(volume, recipe.segmentation);
  const LabelVolume& labels = segmented ? *segmented : made;
  spent.segmentation = seconds_since(started);
  // Skin and bone read the same volume and labels and write nothing shared: they are traced at
  // once, one per core, each into its own mesh (same result as one after the other).
  CaseSurfaces surfaces;
  auto trace = [&](TriangleMesh& mesh, double& seconds, double hu, const SurfaceOptions& options, uint8_t tissue) {
    const auto start = Clock::now();
    mesh = extract_region_surface(volume, labels, {tissue, kTeeth}, hu, options);
    seconds = seconds_since(start);
  };
  const auto& seg = recipe.segmentation;
  run_concurrently({[&] { trace(surfaces.skin, spent.skin, seg.skin_hu, recipe.skin, kSoftTissue); },
                    [&] { trace(surfaces.bone, spent.bone, seg.bone_hu, recipe.bone, kBone); }});
  spent.total = seconds_since(started);
  if (times) *times = spent;
  return surfaces;
}

Json SurfaceRecipe::to_json() const {
  return {{"segmentation",
           {{"skin_hu", segmentation.skin_hu},
            {"bone_hu", segmentation.bone_hu},
            {"teeth_hu", segmentation.teeth_hu},
            {"headrest_gap_mm", segmentation.headrest_gap_mm},
            {"max_restored_piece_mm3", segmentation.max_restored_piece_mm3},
            {"min_bone_island_mm3", segmentation.min_bone_island_mm3},
            {"bone_edge", segmentation.bone_edge_at_half_maximum ? "half-maximum" : "threshold"}}},
          {"skin", surface_json(skin)},
          {"bone", surface_json(bone)}};
}

std::optional<CaseSurfaces> stored_case_surfaces(Archive& archive, int64_t case_id, int64_t series,
                                                 const SurfaceRecipe& recipe) {
  auto key = surfaces_key(archive, series, recipe.to_json());
  auto skin = archive.find_artefact(case_id, kSkinKind, key);
  auto bone = archive.find_artefact(case_id, kBoneKind, key);
  if (!skin || !bone) return std::nullopt;
  log::info("surfaces up to date, reusing them");
  return CaseSurfaces{records::load_mesh_artefact(archive, *skin), records::load_mesh_artefact(archive, *bone), key,
                      true};
}

void store_case_surfaces(Archive& archive, int64_t case_id, int64_t series, CaseSurfaces& surfaces,
                         const SurfaceRecipe& recipe) {
  auto parameters = recipe.to_json();
  surfaces.key = surfaces_key(archive, series, parameters);
  records::store_mesh_artefact(archive, case_id, kSkinKind, surfaces.key, parameters, surfaces.skin);
  records::store_mesh_artefact(archive, case_id, kBoneKind, surfaces.key, parameters, surfaces.bone);
}

CaseSurfaces case_surfaces(Archive& archive, int64_t case_id, int64_t series, const SurfaceRecipe& recipe,
                           const LabelVolume* segmented) {
  if (auto stored = stored_case_surfaces(archive, case_id, series, recipe)) return std::move(*stored);
  auto surfaces = extract_case_surfaces(records::load_archived_series(archive, series), recipe, nullptr, segmented);
  store_case_surfaces(archive, case_id, series, surfaces, recipe);
  return surfaces;
}

}  // namespace maxillo::casework
