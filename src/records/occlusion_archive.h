#pragma once
// Occlusions in the archive, so that the consultation report shows the newest one: the result
// ("occlusion", occlusion.json, occlusion_record.h), its occlusionogram ("occlusionogram", PNG),
// the splint ("splint", STL) and its render ("splint-render", PNG) when one was made, all
// under one key of the run's inputs. The result is stored last, so its presence marks a
// complete set.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "archive/archive.h"
#include "records/occlusion_record.h"

namespace maxillo::records {

// The files of a run's folder (occlusion.json, occlusionogram.png, splint.stl) and the splint's
// render (empty: none). Nothing is stored again under a key the case has already.
struct OcclusionToStore {
  int64_t case_id = 0;
  std::string inputs_hash;
  std::filesystem::path folder;
  bool splint = false;
  std::filesystem::path splint_render;
};

void store_occlusion(Archive& archive, const OcclusionToStore& occlusion);

struct StoredOcclusion {
  std::string source;  // the result's artefact, for errors ("artefact 12 (occlusion)")
  OcclusionRecord record;
  std::filesystem::path occlusionogram;                // object file (PNG without extension)
  std::optional<std::filesystem::path> splint_render;  // the same, when one was stored
};

// The case's newest stored occlusion, if any. Error(kArchiveCorrupt) naming the artefact when
// the result's occlusionogram is missing or the result is damaged.
std::optional<StoredOcclusion> latest_occlusion(const Archive& archive, int64_t case_id);

}  // namespace maxillo::records
