#pragma once
// The pictures of a face prediction: the pre-operative and the predicted face from the same
// cameras (frontal, lateral, oblique), the predicted displacement as a colour map with a colour
// bar, and the uncertainty band across models. The report's soft-tissue section shows them
// (soft_tissue_section.h).
#include <filesystem>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"
#include "geometry/anatomical_frame.h"
#include "casework/softtissue/soft_tissue_prediction.h"

namespace maxillo::casework {

struct SoftTissueViewFiles {
  std::vector<std::filesystem::path> before, after, displacement;  // frontal, lateral, oblique
  double max_displacement_mm = 0;
};

// Renders the nine images into `folder` (created) as soft-tissue-{before,after,displacement}-<view>.png.
SoftTissueViewFiles render_soft_tissue_views(const TriangleMesh& skin_before, const SoftTissuePrediction& prediction,
                                             const AnatomicalFrame& frame, const std::filesystem::path& folder);

// The per-vertex uncertainty band on the predicted skin, frontal and lateral, written into
// `folder` as soft-tissue-uncertainty-<view>.png.
std::vector<std::filesystem::path> render_uncertainty_views(const TriangleMesh& skin_after,
                                                            const std::vector<double>& spread_mm,
                                                            const AnatomicalFrame& frame,
                                                            const std::filesystem::path& folder);

// The soft tissue landmarks a prediction reports when present (mid-sagittal profile points).
const std::vector<std::string>& soft_tissue_landmark_labels();

}  // namespace maxillo::casework
