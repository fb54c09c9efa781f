#pragma once
// `maxillo validate CASE`: a prediction checked against what surgery produced (thesis ch. 6 and 8), for a case with a
// pre-operative CT, a post-operative CT (series role "postop") and a plan:
//   1. the post-operative CT registered rigidly onto the pre-operative one by mutual information on the cranium above
//      the infraorbital rim, which surgery does not touch (imaging/rigid_registration.h);
//   2. each bone segment the plan moves registered by ICP onto the post-operative bone, starting from its planned
//      move: the move actually made (validation/rigid_icp.h);
//   3. the face predicted for the actual moves (casework/softtissue/soft_tissue_prediction.h);
//   4. predicted against post-operative skin in the face without eyes and neck: the signed closest-point distance and
//      the corresponding-point distance after a non-rigid registration (validation/coherent_point_drift.h); negative
//      = the prediction lies behind the real face;
//   5. statistics for the face and per subregion (validation/face_regions.h), an error map and the profiles overlaid.
#include <Eigen/Geometry>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "core/json.h"
#include "imaging/rigid_registration.h"
#include "casework/plan/planned_case.h"
#include "casework/softtissue/soft_tissue_prediction.h"
#include "validation/coherent_point_drift.h"
#include "validation/distance_statistics.h"
#include "validation/face_regions.h"
#include "validation/rigid_icp.h"

namespace maxillo::casework {

struct ValidationOptions {
  RigidRegistrationOptions registration;  // no box: the cranium above the infraorbital rim
  validation::IcpOptions icp;
  SoftTissueOptions soft_tissue;
  validation::FaceRegionOptions regions;
  validation::CpdOptions correspondence;
  bool corresponding_points = true;
  double tolerance_mm = 2.0;        // "% within" of the statistics
  double error_map_range_mm = 3.0;  // colour scale -range..+range

  Json to_json() const;  // the parameters that change the numbers (for the inputs hash)
};

struct SegmentOutcome {
  uint8_t segment = 0;  // planning::Segment
  Eigen::Isometry3d planned = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d actual = Eigen::Isometry3d::Identity();
  double icp_rms_mm = 0;
  double mean_difference_mm = 0;  // mean over the segment's surface of |planned(p) - actual(p)|
  double max_difference_mm = 0;
};

struct RegionStatistics {
  std::string region;  // "face", then the subregions
  validation::DistanceStatistics closest;
  validation::DistanceStatistics corresponding;  // count 0 when not computed
};

struct CaseValidation {
  int64_t case_id = 0;
  int64_t preop_series = 0, postop_series = 0;
  std::string inputs_hash;
  RigidRegistrationResult registration;
  double cranium_icp_rms_mm = 0;  // cranium vs post-operative bone after registration
  std::vector<SegmentOutcome> segments;
  TriangleMesh predicted_skin;                  // pre-operative frame
  TriangleMesh actual_skin;                     // post-operative skin moved into the pre-operative frame
  std::vector<validation::FaceRegion> regions;  // per predicted skin vertex
  std::vector<double> closest_mm;               // per predicted skin vertex; NaN outside the face
  std::vector<double> corresponding_mm;         // the same (empty when not computed)
  std::vector<RegionStatistics> statistics;
  std::vector<std::filesystem::path> error_maps;  // frontal, lateral, oblique PNGs
  std::filesystem::path profile_png;
  Json summary;  // what validation.json holds
  double seconds = 0;
};

// The face region and subregion of each pre-operative skin vertex, cut by the case's landmarks (Sn, Ls, Li, PogS, Or,
// Po, Me; Error naming a missing one) in its anatomical frame; skin lining a cavity (validation/skin_cavities.h) is
// left out.
std::vector<validation::FaceRegion> face_regions_of(const TriangleMesh& preop_skin, const LandmarkSet& landmarks,
                                                    const validation::FaceRegionOptions& options = {});

// The case's newest post-operative series (role "postop"), if any.
std::optional<int64_t> postop_series(const CaseContents& contents);

// The key of a validation's inputs: both series' contents, the plan, the landmarks and the options. nullopt when the
// case lacks a post-operative CT, a plan or landmarks (cheap: reads no image).
std::optional<std::string> validation_inputs_hash(const Archive& archive, int64_t case_id,
                                                  const ValidationOptions& options);

// One case's part of validation_inputs_hashes.
struct CaseInputsHash {
  std::optional<std::string> hash;        // nothing: no post-operative CT, plan or landmarks
  std::exception_ptr error;               // what reading this case's records threw (Error(kNotFound): no such case)
  std::vector<ArtefactRecord> artefacts;  // the case's, read on the way: its stored validations are among them
};
// validation_inputs_hash of many cases, read set-wise: a few queries per 4,096 cases instead of several per case (the
// nightly scan; on a server each query is a network round trip). Every id of `case_ids` is in the result; a case whose
// records cannot be read carries its error, and the others their hashes.
std::map<int64_t, CaseInputsHash> validation_inputs_hashes(const Archive& archive, const std::vector<int64_t>& case_ids,
                                                           const ValidationOptions& options);

// Runs the validation and writes its files into `out` (created): error-map-<view>.png, profile.png,
// predicted-skin.vtp and actual-skin.vtp (with the distances), validation.json. `planned`: the case as
// load_planned_case gives it, when the caller has it already.
CaseValidation validate_case(Archive& archive, int64_t case_id, const ValidationOptions& options,
                             const std::filesystem::path& out, const PlannedCase* planned = nullptr);

}  // namespace maxillo::casework
