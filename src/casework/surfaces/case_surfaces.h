#pragma once
// The skin and bone surfaces of a case's CT series: volume -> tissue segmentation (head rest
// removed) -> iso-surfaces -> smoothing and decimation. Stored in the archive as artefacts
// keyed by the series content and the recipe, so a second request reuses them.
#include <cstdint>
#include <optional>

#include "archive/archive.h"
#include "core/json.h"
#include "core/triangle_mesh.h"
#include "imaging/segmentation.h"
#include "mesh/surface_extraction.h"

namespace maxillo::casework {

struct SurfaceRecipe {
  SegmentationOptions segmentation;
  SurfaceOptions skin{.keep_largest_components = 1, .target_triangles = 150000};
  SurfaceOptions bone{.keep_largest_components = 8, .min_component_fraction = 0.02, .target_triangles = 200000};

  Json to_json() const;  // every parameter, for the derivation key and the artefact record
};

struct CaseSurfaces {
  TriangleMesh skin;
  TriangleMesh bone;
  std::string key;      // derivation key of both surfaces
  bool reused = false;  // true when both came from the archive
};

// Seconds each step of extract_case_surfaces took; skin and bone run at the same time, so the
// total (wall clock) is about segmentation + the longer of the two on a machine with two cores.
struct SurfaceTimes {
  double segmentation = 0, skin = 0, bone = 0, total = 0;
};

// The surfaces of a volume, computed (no archive): segmentation, then skin and bone. `segmented`, when given, is
// segment_tissues(volume, recipe.segmentation) made earlier; the segmentation is then not repeated.
CaseSurfaces extract_case_surfaces(const Volume& volume, const SurfaceRecipe& recipe = {},
                                   SurfaceTimes* times = nullptr, const LabelVolume* segmented = nullptr);

// Surfaces of `series` (a CT series of the case). Throws what volume loading and
// segmentation throw (Error naming the file or series). `segmented` as above, for that series.
CaseSurfaces case_surfaces(Archive& archive, int64_t case_id, int64_t series, const SurfaceRecipe& recipe = {},
                           const LabelVolume* segmented = nullptr);

// The two halves of case_surfaces, for callers that extract the surfaces on another thread while
// the archive stays on theirs: the stored surfaces of `series` if they are up to date (reused set),
// and storing what extract_case_surfaces made of the series' volume (sets the key).
std::optional<CaseSurfaces> stored_case_surfaces(Archive& archive, int64_t case_id, int64_t series,
                                                 const SurfaceRecipe& recipe = {});
void store_case_surfaces(Archive& archive, int64_t case_id, int64_t series, CaseSurfaces& surfaces,
                         const SurfaceRecipe& recipe = {});

}  // namespace maxillo::casework
