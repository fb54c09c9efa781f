#include "records/simulation_archive.h"

#include "archive/artefact_kind.h"
#include "records/stored_artefact.h"

namespace maxillo::records {
namespace {

const std::string kSimulationKind = kind_name(ArtefactKind::kSimulation);
const std::string kImageKind = kind_name(ArtefactKind::kSimulationImage);

}  // namespace

void store_simulation(Archive& archive, const SimulationToStore& s) {
  for (const auto& png : s.pictures)
    store_picture(archive, s.case_id, ArtefactKind::kSimulationImage, s.inputs_hash, png);
  const std::string summary = to_json(s.summary).dump(2) + "\n";
  archive.add_artefact(
      NewArtefact{s.case_id, kSimulationKind, archive.store_object(summary), "application/json", s.inputs_hash});
}

std::optional<StoredSimulation> latest_simulation(const Archive& archive, int64_t case_id) {
  const auto artefacts = archive.artefacts(case_id);  // by id: later entries are newer
  const ArtefactRecord* found = newest_artefact(artefacts, kSimulationKind);
  if (!found) return std::nullopt;
  StoredSimulation stored;
  stored.case_id = case_id;
  stored.source = artefact_source(*found);
  stored.summary = read_simulation_summary(artefact_json(archive, *found), stored.source);
  // The pictures stored before the summary under its key; a later run of the same inputs
  // replaces each by name.
  for (const auto& a : artefacts) {
    if (a.kind != kImageKind || a.inputs_hash != found->inputs_hash || a.id > found->id) continue;
    stored.pictures[picture_name(a)] = archive.object_path(a.object_sha256);
  }
  return stored;
}

}  // namespace maxillo::records
