#pragma once
// Pictures a surgeon checks the landmarks on at a glance: the bone (opaque) under the skin
// (translucent), each landmark drawn as a disc over both and labelled, in three views from the
// same cameras as the case's views (casework/surfaces/case_views.h):
//   frontal        every landmark;
//   right lateral  the midline landmarks and the right-sided ones;
//   left lateral   the left-sided ones (the right lateral hides them behind the skull).
// Colours say where a point came from: given by hand (green), found automatically with every
// check passed (blue), flagged by a check or weak evidence (orange, the warning colour).
// Rendered off-screen once per set and surfaces, and stored as "landmark-render" pictures.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "casework/surfaces/case_surfaces.h"
#include "casework/surfaces/case_views.h"
#include "records/case_landmarks.h"
#include "render/anatomical_views.h"
#include "render/scene.h"

namespace maxillo::casework {

inline constexpr render::ColourRGB kGivenLandmarkColour{0.10, 0.62, 0.25};
inline constexpr render::ColourRGB kAutomaticLandmarkColour{0.12, 0.40, 0.90};
inline constexpr render::ColourRGB kFlaggedLandmarkColour{1.00, 0.45, 0.00};

struct LandmarkView {
  render::StandardView view;
  std::filesystem::path png;  // the stored object (read-only)
  std::string caption;        // e.g. "right lateral: midline and right-sided landmarks"
};

// The markers of `stored` seen in `view` (the landmarks that view shows, coloured by source
// and status), in the set's order.
std::vector<render::SceneMarker> landmark_markers(const records::StoredLandmarks& stored, render::StandardView view);

// Renders (or reuses) the three pictures of the set on the case's surfaces.
std::vector<LandmarkView> landmark_views(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                                         const records::StoredLandmarks& stored, const ViewRecipe& recipe = {});

}  // namespace maxillo::casework
