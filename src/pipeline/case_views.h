#pragma once
// The standard clinical views (frontal, right lateral, oblique) of a case's skin over its bone,
// rendered off-screen and stored in the archive as PNG artefacts.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "pipeline/case_surfaces.h"
#include "render/anatomical_views.h"

namespace maxillo::pipeline {

struct CaseView {
  render::StandardView view;
  std::filesystem::path png;  // the stored object (read-only)
  std::string caption;        // e.g. "frontal (Frankfort frame)"
};

struct ViewRecipe {
  int image_size_px = 1024;
  double skin_opacity = 0.45;  // skin translucent over ivory bone, so both read
};

// Renders (or reuses) the three standard views. The camera frame comes from the landmarks
// (Frankfort horizontal) when they allow it, else from the patient axes.
std::vector<CaseView> case_views(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                                 const LandmarkSet& landmarks, const ViewRecipe& recipe = {});

}  // namespace maxillo::pipeline
