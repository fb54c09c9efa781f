#pragma once
// What a plan gives the operating room and the report besides numbers: the bone cut into its
// segments (planning/osteotomy.h), the planned bone surfaces as STL, the stereolithographic
// transfer model with a tube along each distraction screw (transfer_model.h), and
// renders of the planned skeleton with the screw axes (plan_views.h).
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ceph/landmark.h"
#include "core/json.h"
#include "core/volume.h"
#include "planning/osteotomy.h"
#include "planning/plan_application.h"
#include "records/plan_result_record.h"
#include "casework/plan/transfer_model.h"
#include "report/report_model.h"

namespace maxillo::casework {

struct PlanOutputs {
  std::vector<planning::SegmentStats> segments;                      // volumes of the cut segments
  int64_t bone_voxels = 0;                                           // input bone and teeth (== the segments' sum)
  std::optional<TransferModel> transfer_model;                       // with a distraction only
  std::vector<std::pair<std::string, std::filesystem::path>> files;  // label -> file
  std::vector<std::filesystem::path> renders;                        // frontal, lateral, oblique
};

// `labels` in the phantom tissue convention (sample/phantom.h; planning/jaw_separation.h makes
// it from a CT segmentation). Writes into out_dir (created).
PlanOutputs write_plan_outputs(const LabelVolume& labels, const LandmarkSet& landmarks,
                               const planning::PlanResult& result, const std::filesystem::path& out_dir);

// The segments' volumes and the transfer model's facts, for plan-result.json (key "osteotomy").
Json plan_outputs_json(const PlanOutputs& outputs);

// Report blocks for the planning section from the stored result's osteotomy outputs: the
// segments' volumes and the transfer model (the renders come with the result's files).
std::vector<report::Block> plan_output_blocks(const records::PlanResultRecord::Osteotomy& osteotomy);

}  // namespace maxillo::casework
