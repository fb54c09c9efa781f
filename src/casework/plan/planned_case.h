#pragma once
// A case of the archive with its surgery planned: what the face prediction, the synthetic post-operative scan and the
// validation all start from. The pre-operative CT segmented once (casework/surfaces/case_tissues.h), the newest plan
// applied to it, its bone cut into segments by the plan's osteotomies, each segment's planned move, and the
// pre-operative skin surface.
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <memory>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "core/triangle_mesh.h"
#include "core/volume.h"
#include "casework/surfaces/case_tissues.h"
#include "records/plan_archive.h"
#include "casework/softtissue/soft_tissue_prediction.h"
#include "planning/osteotomy.h"
#include "planning/plan_application.h"

namespace maxillo::casework {

using SegmentMoves = std::map<uint8_t, Eigen::Isometry3d>;  // planning::Segment value -> rigid
                                                            // move, LPS mm

struct PlannedCase {
  int64_t case_id = 0;
  int64_t preop_series = 0;
  Volume preop_ct;
  LandmarkSet landmarks;  // the newest landmark set
  CaseTissues tissues;
  records::StoredPlan plan;       // the newest plan
  planning::OsteotomyResult cut;  // bone segments of tissues.jaws
  SegmentMoves planned_moves;     // the segments the plan moves: stored by `plan apply`, or applied here
  TriangleMesh skin;              // pre-operative skin (case_surfaces.h)

  // The face's tet model of these tissues and landmarks (casework/softtissue/soft_tissue_prediction.h), built on first
  // use for the options' meshing and shared by every prediction made from this case: the planned
  // move of the synthetic post-operative scan, the moves the validation finds. Any thread. A
  // PlannedCase not made by load_planned_case builds a new model at each call.
  std::shared_ptr<const FaceModel> face_model(const SoftTissueOptions& options) const;

  struct FaceModels;  // the models built so far, by key (planned_case.cpp); shared by copies
  std::shared_ptr<FaceModels> face_models;
};

// Error(kNotFound) naming the case when it has no plan, no landmarks or no CT; what loading, segmentation and
// apply_plan throw otherwise. `tissues`: the case's segmented CT when the caller has it already (e.g. from `plan
// apply`); null segments it. The planned moves come from the result `plan apply` stored for this plan and these
// landmarks (plan_archive.h); the plan is applied again only when there is none.
PlannedCase load_planned_case(Archive& archive, int64_t case_id, const CaseTissues* tissues = nullptr);

SegmentMoves moves_by_segment(const std::vector<planning::PlannedMove>& moves);

// The moves of `plan` on this case: those `plan apply` stored for its text and `landmarks`
// when there are, else apply_plan's on `segmentation`. `reused` says which.
std::vector<planning::PlannedMove> plan_moves(const Archive& archive, int64_t case_id, const planning::Plan& plan,
                                              const LandmarkSet& landmarks, const LabelVolume& segmentation,
                                              bool* reused = nullptr);

}  // namespace maxillo::casework
