#pragma once
// The standard clinical views (frontal, right lateral, oblique) of a case's face (opaque skin)
// and of its skeleton (bone), from the same cameras, rendered off-screen and stored in the
// archive as PNG artefacts.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "casework/surfaces/case_surfaces.h"
#include "render/anatomical_views.h"

namespace maxillo::casework {

enum class ViewedTissue { Skin, Bone };
std::string_view name_of(ViewedTissue tissue);  // "skin", "bone"

struct CaseView {
  ViewedTissue tissue;
  render::StandardView view;
  std::filesystem::path png;  // the stored object (read-only)
  std::string caption;        // e.g. "skin, frontal"
};

struct ViewRecipe {
  int image_size_px = 1024;
};

// Renders (or reuses) the three standard views of skin, then of bone (six images, in that
// order). Both rows share one camera per view, fitted to the skin, so they superimpose. The camera frame comes from the landmarks
// (Frankfort horizontal) when they allow it, else from the patient axes.
std::vector<CaseView> case_views(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                                 const LandmarkSet& landmarks, const ViewRecipe& recipe = {});

}  // namespace maxillo::casework
