#include "pipeline/case_landmarks.h"

#include "ceph/landmark_io.h"
#include "core/json.h"

namespace maxillo::pipeline {
namespace {
constexpr const char* kLandmarksKind = "landmarks";
}

void attach_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& landmarks, const std::string& source) {
  auto text = format_landmarks(landmarks, LandmarkFormat::kSlicerMarkupsJson);
  auto sha = archive.store_object(text);
  archive.add_artefact(NewArtefact{case_id, kLandmarksKind, sha, "application/json", sha,
                                   Json{{"source", source}, {"count", landmarks.size()}, {"frame", "LPS"}}.dump()});
}

LandmarkSet latest_landmarks(const Archive& archive, int64_t case_id) {
  const ArtefactRecord* newest = nullptr;
  auto artefacts = archive.artefacts(case_id);
  for (const auto& a : artefacts)
    if (a.kind == kLandmarksKind && (!newest || a.id > newest->id)) newest = &a;
  if (!newest) return {};
  auto bytes = archive.read_object(newest->object_sha256);
  std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  return parse_landmarks(text, LandmarkFormat::kSlicerMarkupsJson, "archive object " + newest->object_sha256);
}

}  // namespace maxillo::pipeline
