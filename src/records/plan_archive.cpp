#include "records/plan_archive.h"

#include <algorithm>

#include "archive/artefact_kind.h"
#include "ceph/landmark_io.h"
#include "core/error.h"
#include "core/sha256.h"
#include "records/stored_artefact.h"

namespace maxillo::records {
namespace {

const std::string kPlanKind = kind_name(ArtefactKind::kPlan);
const std::string kPlanResultKind = kind_name(ArtefactKind::kPlanResult);

std::vector<ArtefactRecord> artefacts_of_kind(const Archive& archive, int64_t case_id, const std::string& kind) {
  auto all = archive.artefacts(case_id);
  std::vector<ArtefactRecord> selected;
  std::copy_if(all.begin(), all.end(), std::back_inserter(selected), [&](const auto& a) { return a.kind == kind; });
  std::sort(selected.begin(), selected.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return selected;
}

}  // namespace

StoredPlan store_plan(Archive& archive, int64_t case_id, const planning::Plan& plan) {
  const std::string text = planning::serialise_plan(plan);
  const int version = static_cast<int>(artefacts_of_kind(archive, case_id, kPlanKind).size()) + 1;
  const std::string sha = archive.store_object(text);
  const Json parameters{
      {"version", version}, {"format_version", plan.format_version}, {"description", plan.description}};
  const std::string inputs = sha256_hex(text + "\nversion " + std::to_string(version));
  const int64_t id =
      archive.add_artefact(NewArtefact{case_id, kPlanKind, sha, "application/json", inputs, parameters.dump()});
  for (StoredPlan& stored : plan_history(archive, case_id))
    if (stored.artefact_id == id) return stored;
  return StoredPlan{id, version, "", "", sha, plan};
}

std::vector<StoredPlan> plan_history(const Archive& archive, int64_t case_id) {
  std::vector<StoredPlan> history;
  int version = 0;
  for (const ArtefactRecord& record : artefacts_of_kind(archive, case_id, kPlanKind)) {
    StoredPlan stored;
    stored.artefact_id = record.id;
    stored.version = ++version;
    stored.created_at = record.created_at;
    stored.program_version = record.program_version;
    stored.sha256 = record.object_sha256;
    stored.plan = planning::parse_plan(artefact_text(archive, record), "plan artefact " + std::to_string(record.id));
    history.push_back(std::move(stored));
  }
  return history;
}

std::optional<StoredPlan> latest_plan(const Archive& archive, int64_t case_id) {
  auto history = plan_history(archive, case_id);
  if (history.empty()) return std::nullopt;
  return history.back();
}

std::optional<std::string> latest_plan_sha256(const std::vector<ArtefactRecord>& case_artefacts) {
  const ArtefactRecord* newest = newest_artefact(case_artefacts, kPlanKind);
  if (!newest) return std::nullopt;
  return newest->object_sha256;
}

std::string plan_application_key(const std::string& plan_sha256, const LandmarkSet& landmarks) {
  Sha256 hash;
  hash.update("plan " + plan_sha256 + "\nlandmarks\n");
  hash.update(format_landmarks(landmarks, LandmarkFormat::kSlicerMarkupsJson));
  return hash.hex_digest();
}

void store_plan_result(Archive& archive, int64_t case_id, const StoredPlan& plan, const LandmarkSet& landmarks,
                       const Json& result) {
  const std::string text = result.dump(2) + "\n";
  const std::string sha = archive.store_object(text);
  const Json parameters{{"plan_artefact", plan.artefact_id}, {"plan_version", plan.version}};
  archive.add_artefact(NewArtefact{case_id, kPlanResultKind, sha, "application/json",
                                   plan_application_key(plan.sha256, landmarks), parameters.dump()});
}

std::optional<std::vector<planning::PlannedMove>> stored_plan_moves(const Archive& archive, int64_t case_id,
                                                                    const std::string& plan_sha256,
                                                                    const LandmarkSet& landmarks) {
  const std::string key = plan_application_key(plan_sha256, landmarks);
  const auto results = artefacts_of_kind(archive, case_id, kPlanResultKind);
  const auto newest =
      std::find_if(results.rbegin(), results.rend(), [&](const auto& a) { return a.inputs_hash == key; });
  if (newest == results.rend()) return std::nullopt;
  return planning::planned_moves_from_json(artefact_json(archive, *newest), artefact_source(*newest));
}

std::optional<PlanResultRecord> latest_plan_result(const Archive& archive, int64_t case_id) {
  const auto results = artefacts_of_kind(archive, case_id, kPlanResultKind);
  if (results.empty()) return std::nullopt;
  return read_plan_result_record(artefact_json(archive, results.back()), artefact_source(results.back()));
}

}  // namespace maxillo::records
