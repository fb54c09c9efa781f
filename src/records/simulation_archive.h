#pragma once
// Face predictions in the archive, so that `maxillo report` shows the newest one without
// predicting again: the summary ("simulation", JSON, simulation_summary.h) and the pictures
// ("simulation-image", PNG, each named in the artefact's parameters by its file's stem, e.g.
// "soft-tissue-after-lateral"), keyed by the prediction's inputs. The summary is stored last,
// so its presence marks a complete result.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "records/simulation_summary.h"

namespace maxillo::records {

struct SimulationToStore {
  int64_t case_id = 0;
  std::string inputs_hash;  // of the case's series, plan, landmarks and options
  SimulationSummary summary;
  std::vector<std::filesystem::path> pictures;  // PNG files
};

void store_simulation(Archive& archive, const SimulationToStore& simulation);

struct StoredSimulation {
  int64_t case_id = 0;
  std::string source;  // the summary's artefact, for errors ("artefact 12 (simulation)")
  SimulationSummary summary;
  std::map<std::string, std::filesystem::path> pictures;  // name -> object file (PNG without extension)
};

// The case's newest stored prediction, if any; its pictures are those stored with it.
std::optional<StoredSimulation> latest_simulation(const Archive& archive, int64_t case_id);

}  // namespace maxillo::records
