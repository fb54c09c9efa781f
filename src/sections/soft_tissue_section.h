#pragma once
// The "soft_tissue" section of the consultation report: the pre-operative face and the
// predicted face side by side from the same cameras (frontal, lateral, oblique), the predicted
// displacement as a colour map with a colour bar, the model's facts and the displacement of
// the soft tissue landmarks in the anatomical frame.
#include <filesystem>
#include <string>
#include <vector>

#include "ceph/landmark.h"
#include "casework/case_simulation.h"
#include "casework/soft_tissue_prediction.h"
#include "casework/soft_tissue_views.h"
#include "render/anatomical_views.h"
#include "report/report_model.h"

namespace maxillo::sections {

struct SoftTissueSummary {
  std::string plan_text;  // e.g. "Le Fort I, maxilla 6.0 mm advancement"
  casework::SoftTissueOptions options;
  LandmarkSet soft_landmarks;  // pre-operative soft tissue landmarks to report (may be empty)
};

report::Section soft_tissue_section(const casework::SoftTissuePrediction& prediction,
                                    const casework::SoftTissueViewFiles& views, const AnatomicalFrame& frame,
                                    const SoftTissueSummary& summary);

// The section of a case's simulation (case_simulation.h), with its uncertainty band when it has one.
report::Section soft_tissue_section(const casework::SimulationResult& result,
                                    const casework::SimulationRequest& request);

}  // namespace maxillo::sections
