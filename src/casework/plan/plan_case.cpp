#include "casework/plan/plan_case.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "records/case_landmarks.h"
#include "records/derivation.h"
#include "casework/landmarks/automatic_landmarks.h"
#include "casework/landmarks/case_orientation.h"
#include "casework/surfaces/case_tissues.h"
#include "casework/plan/plan_outputs.h"
#include "records/plan_result_record.h"

#include <array>

namespace maxillo::casework {

CasePlanResult apply_case_plan(Archive& archive, int64_t case_id, const std::filesystem::path& out_dir,
                               const CaseTissues* tissues, bool accept_flagged) {
  const std::string subject = "case:" + std::to_string(case_id);
  CasePlanResult out;
  const auto plan = records::latest_plan(archive, case_id);
  if (!plan) throw Error(ErrorCode::kNotFound, subject, "the case has no plan: make one with `maxillo plan create`");
  out.plan = *plan;
  require_trusted_orientation(archive, case_id, "planning");
  const auto stored = case_landmarks(archive, case_id);
  if (!stored || stored->landmarks.empty())
    throw Error(ErrorCode::kNotFound, subject, "the case has no landmarks and no CT to find them on");
  require_confirmed_landmarks(*stored, subject, accept_flagged);
  const LandmarkSet& landmarks = stored->landmarks;

  out.tissues = tissues ? *tissues : load_case_tissues(archive, case_id, landmarks);
  out.result =
      planning::apply_plan(plan->plan, out.tissues.segmentation, landmarks, planning::segmentation_anatomy_labels());

  // The bone cut into segments, the planned segment surfaces, the transfer model and the
  // renders of the planned skeleton (plan_outputs.h); they need the jaws told apart.
  const auto outputs = write_plan_outputs(out.tissues.jaws, landmarks, out.result, std::filesystem::absolute(out_dir));
  const std::array<std::string, 3> views{"frontal", "right lateral", "oblique"};
  for (size_t v = 0; v < outputs.renders.size() && v < views.size(); ++v)
    out.result.files.push_back({"Planned skeleton, " + views[v], outputs.renders[v]});
  for (const auto& file : outputs.files) out.result.files.push_back(file);

  std::filesystem::create_directories(out_dir);
  out.result_json = out_dir / "plan-result.json";
  const Json json = records::plan_result_record_json(out.result, plan_outputs_json(outputs));
  write_file_atomically(out.result_json, json.dump(2) + "\n");
  records::store_plan_result(archive, case_id, out.plan, landmarks, json);
  return out;
}

}  // namespace maxillo::casework
