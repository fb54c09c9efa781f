#include "casework/plan/planned_case.h"

#include <mutex>

#include "casework/landmarks/automatic_landmarks.h"
#include "core/error.h"
#include "core/log.h"
#include "core/sha256.h"
#include "imaging/volume_assembly.h"
#include "imaging/hounsfield_reading.h"
#include "records/archived_series.h"
#include "records/case_landmarks.h"
#include "casework/surfaces/case_surfaces.h"
#include "records/derivation.h"
#include "planning/distractor_checks.h"

namespace maxillo::casework {

struct PlannedCase::FaceModels {
  std::mutex mutex;
  std::map<std::string, std::shared_ptr<const FaceModel>> by_key;
};

SegmentMoves moves_by_segment(const std::vector<planning::PlannedMove>& moves) {
  SegmentMoves by_segment;
  for (const auto& m : moves) by_segment[uint8_t(m.segment)] = m.transform;
  return by_segment;
}

std::vector<planning::PlannedMove> plan_moves(const Archive& archive, int64_t case_id, const planning::Plan& plan,
                                              const LandmarkSet& landmarks, const LabelVolume& segmentation,
                                              bool* reused) {
  const std::string plan_sha256 = sha256_hex(planning::serialise_plan(plan));
  auto stored = records::stored_plan_moves(archive, case_id, plan_sha256, landmarks);
  if (reused) *reused = bool(stored);
  if (stored) return std::move(*stored);
  log::info("plan: no stored result for this plan and these landmarks; applying it");
  return planning::apply_plan(plan, segmentation, landmarks, planning::segmentation_anatomy_labels()).moves;
}

PlannedCase load_planned_case(Archive& archive, int64_t case_id, const CaseTissues* tissues) {
  const std::string subject = "case:" + std::to_string(case_id);
  PlannedCase c;
  c.case_id = case_id;
  const auto stored = case_landmarks(archive, case_id);
  if (!stored || stored->landmarks.empty())
    throw Error(ErrorCode::kNotFound, subject, "the case has no landmarks and no CT to find them on");
  c.landmarks = stored->landmarks;
  auto plan = records::latest_plan(archive, case_id);
  if (!plan) throw Error(ErrorCode::kNotFound, subject, "the case has no plan: make one first (maxillo plan create)");
  c.plan = std::move(*plan);
  c.preop_series = records::primary_series(archive.case_contents(case_id));
  c.face_models = std::make_shared<PlannedCase::FaceModels>();
  // Read as HU (a cone-beam scan's grey values mapped, hounsfield_reading.h): every step below thresholds in HU.
  c.preop_ct = as_hounsfield_units(records::load_archived_series(archive, c.preop_series));
  c.tissues = tissues ? *tissues : segment_case_tissues(c.preop_ct, c.landmarks);
  c.planned_moves = moves_by_segment(plan_moves(archive, case_id, c.plan.plan, c.landmarks, c.tissues.segmentation));
  c.cut = planning::cut_skeleton(c.tissues.jaws, planning::resolve_osteotomies(c.plan.plan.osteotomies, c.landmarks));
  const SurfaceRecipe recipe;
  c.skin = case_surfaces(archive, case_id, c.preop_series, recipe, c.tissues.ct_labels_for(recipe.segmentation)).skin;
  return c;
}

std::shared_ptr<const FaceModel> PlannedCase::face_model(const SoftTissueOptions& options) const {
  if (!face_models) return std::make_shared<const FaceModel>(build_face_model(tissues.jaws, landmarks, options));
  const std::string key = face_model_key(tissues.jaws, landmarks, options);
  std::lock_guard lock(face_models->mutex);
  auto& model = face_models->by_key[key];
  if (!model) model = std::make_shared<const FaceModel>(build_face_model(tissues.jaws, landmarks, options));
  return model;
}

}  // namespace maxillo::casework
