#pragma once
// `maxillo simulate` for a case of the archive: the CT of the case segmented and its jaws told
// apart (planning/jaw_separation.h), the plan's osteotomies and moves applied to the bone
// segments, the face predicted (soft_tissue_prediction.h), optionally the uncertainty across
// models and Poisson ratios, and the results written as files and pictures and stored in the
// archive (records/simulation_archive.h), where the consultation report finds the newest.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "core/json.h"
#include "casework/surfaces/case_tissues.h"
#include "casework/softtissue/soft_tissue_prediction.h"
#include "records/simulation_summary.h"
#include "casework/softtissue/soft_tissue_views.h"
#include "geometry/anatomical_frame.h"
#include "planning/plan.h"

namespace maxillo::casework {

struct SimulationRequest {
  planning::Plan plan;
  std::string plan_text;  // one line for the report, e.g. "maxilla 6.0 mm advancement"
  SoftTissueOptions options;
  bool uncertainty = false;  // also solve with every model and Poisson 0.45 and 0.49
  // The case's face model when the caller has it (PlannedCase::face_model with these options);
  // null: built here. A model of other tissues, landmarks or meshing options is refused.
  std::shared_ptr<const FaceModel> face_model;
  std::filesystem::path out;    // folder (created) for the files and pictures
  bool accept_flagged = false;  // use automatic landmarks that failed a check (automatic_landmarks.h)
};

struct Uncertainty {
  std::vector<std::string> runs;              // "mtm nu=0.46", ...
  std::vector<double> run_max_mm;             // each run's largest skin displacement
  std::vector<double> run_p95_from_first_mm;  // each run's P95 distance from the first run, moved skin
  std::vector<double> spread_mm;              // per skin vertex: largest distance of a run from the mean
  double p95_mm = 0, max_mm = 0;              // over the skin vertices that moved
};

struct SimulationResult {
  SoftTissuePrediction prediction;
  TriangleMesh skin_before;
  std::optional<Uncertainty> uncertainty;
  SoftTissueViewFiles views;
  std::vector<std::filesystem::path> uncertainty_views;  // frontal, lateral; with `uncertainty` only
  AnatomicalFrame frame;                                 // of the case's landmarks: the views' cameras
  std::vector<std::filesystem::path> files;              // predicted skin (vtp, stl, ply), model (vtu), json
  records::SimulationSummary summary;                    // what simulation.json holds, and the archive keeps
  bool reused_plan_application = false;                  // the plan's moves came from `plan apply`'s stored result
  // Set when the model asked for did not run and another one solved the face (predict_face).
  std::optional<records::SimulationSummary::ModelFallback> fallback;
};

// The face predicted with the model asked for. The non-linear FEM can fail to converge on a real
// head (a sliver turned inside out by the bone's move; docs/ARCHITECTURE.md); the linear FEM,
// which solves the same equations for small strains, then predicts the face on the same model,
// and `fallback` says which model was asked for and why it did not run. Every other failure is
// thrown. `model`: the case's face model, or null to build it here (once, for both solves).
SoftTissuePrediction predict_face(const SoftTissueInput& input, const SoftTissueOptions& options,
                                  const FaceModel* model,
                                  std::optional<records::SimulationSummary::ModelFallback>& fallback);

// The uncertainty band: the same model re-solved with every other model and with Poisson
// ratios 0.45 and 0.49 (the spread of plausible answers, not an error bound).
Uncertainty prediction_uncertainty(const SoftTissuePrediction& base, const TriangleMesh& skin,
                                   const SoftTissueOptions& options);

// `tissues`: the case's segmented CT when the caller has it already (e.g. from `plan apply`);
// null loads and segments it.
SimulationResult simulate_case(Archive& archive, int64_t case_id, const SimulationRequest& request,
                               const CaseTissues* tissues = nullptr);

// The plan of a Le Fort I advancement by `advancement_mm` (forward, in the planning frame).
planning::Plan le_fort_advancement_plan(double advancement_mm);

}  // namespace maxillo::casework
