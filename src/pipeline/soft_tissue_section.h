#pragma once
// The "soft_tissue" section of the consultation report: the pre-operative face and the
// predicted face side by side from the same cameras (frontal, lateral, oblique), the predicted
// displacement as a colour map with a colour bar, the model's facts and the displacement of
// the soft tissue landmarks in the anatomical frame.
#include <filesystem>
#include <string>
#include <vector>

#include "ceph/landmark.h"
#include "pipeline/soft_tissue_prediction.h"
#include "render/anatomical_views.h"
#include "report/report_model.h"

namespace maxillo::pipeline {

struct SoftTissueViewFiles {
  std::vector<std::filesystem::path> before, after, displacement;  // frontal, lateral, oblique
  double max_displacement_mm = 0;
};

// Renders the nine images into `folder` (created) as soft-tissue-{before,after,displacement}-<view>.png.
SoftTissueViewFiles render_soft_tissue_views(const TriangleMesh& skin_before, const SoftTissuePrediction& prediction,
                                             const AnatomicalFrame& frame, const std::filesystem::path& folder);

// The per-vertex uncertainty band on the predicted skin (frontal and lateral), as an image grid
// of soft-tissue-uncertainty-<view>.png files written into `folder`.
report::ImageGrid render_uncertainty_views(const TriangleMesh& skin_after, const std::vector<double>& spread_mm,
                                           const AnatomicalFrame& frame, const std::filesystem::path& folder);

struct SoftTissueSummary {
  std::string plan_text;  // e.g. "Le Fort I, maxilla 6.0 mm advancement"
  SoftTissueOptions options;
  LandmarkSet soft_landmarks;  // pre-operative soft tissue landmarks to report (may be empty)
};

report::Section soft_tissue_section(const SoftTissuePrediction& prediction, const SoftTissueViewFiles& views,
                                    const AnatomicalFrame& frame, const SoftTissueSummary& summary);

// The soft tissue landmarks the report lists when present (mid-sagittal profile points).
const std::vector<std::string>& soft_tissue_landmark_labels();

}  // namespace maxillo::pipeline
