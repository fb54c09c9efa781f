#include "records/occlusion_archive.h"

#include "archive/artefact_kind.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "records/stored_artefact.h"

namespace maxillo::records {
namespace {

void store_file(Archive& archive, const OcclusionToStore& o, ArtefactKind kind, const std::filesystem::path& file,
                const std::string& media_type) {
  const std::string sha = archive.store_object(read_file(file));
  archive.add_artefact(NewArtefact{o.case_id, kind_name(kind), sha, media_type, o.inputs_hash, "{}"});
}

}  // namespace

void store_occlusion(Archive& archive, const OcclusionToStore& o) {
  if (archive.find_artefact(o.case_id, kind_name(ArtefactKind::kOcclusion), o.inputs_hash))
    return;  // same inputs, same program: stored already
  store_file(archive, o, ArtefactKind::kOcclusionogram, o.folder / "occlusionogram.png", "image/png");
  if (o.splint) store_file(archive, o, ArtefactKind::kSplint, o.folder / "splint.stl", "model/stl");
  if (!o.splint_render.empty()) store_file(archive, o, ArtefactKind::kSplintRender, o.splint_render, "image/png");
  store_file(archive, o, ArtefactKind::kOcclusion, o.folder / "occlusion.json", "application/json");
}

std::optional<StoredOcclusion> latest_occlusion(const Archive& archive, int64_t case_id) {
  const auto artefacts = archive.artefacts(case_id);
  const ArtefactRecord* result = newest_artefact(artefacts, kind_name(ArtefactKind::kOcclusion));
  if (!result) return std::nullopt;
  StoredOcclusion stored;
  stored.source = artefact_source(*result);
  stored.record = read_occlusion_record(artefact_json(archive, *result), stored.source);
  // The key, not the order, ties the files to the result: archives written before the result was
  // stored last hold them after it.
  const ArtefactRecord* gram = newest_with_key(artefacts, ArtefactKind::kOcclusionogram, result->inputs_hash);
  if (!gram) throw Error(ErrorCode::kArchiveCorrupt, stored.source, "its occlusionogram is not stored");
  stored.occlusionogram = archive.object_path(gram->object_sha256);
  if (const ArtefactRecord* render = newest_with_key(artefacts, ArtefactKind::kSplintRender, result->inputs_hash))
    stored.splint_render = archive.object_path(render->object_sha256);
  return stored;
}

}  // namespace maxillo::records
