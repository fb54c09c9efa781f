// Derived artefacts (reports, renders, surfaces...): stored objects with their provenance.
#include "archive/archive_sql.h"
#include "archive/archive_state.h"
#include "archive/journalled_transaction.h"
#include "core/atomic_file.h"
#include "core/json.h"
#include "core/sha256.h"
#include "core/version.h"

namespace maxillo {
namespace {

ArtefactRecord artefact_from(const db::Statement& r) {
  return {r.integer(0), r.integer(1), r.text(2), r.text(3), r.text(4), r.text(5), r.text(6), r.text(7), r.text(8)};
}

}  // namespace

std::string Archive::store_object(std::span<const std::byte> bytes) {
  std::string sha = sha256_hex(bytes);
  StoreLock lock(*state_, LockKind::Shared);
  state_->objects.put(sha, bytes);
  state_->objects.make_durable();
  JournalledTransaction transaction(state_->db, state_->journal, "object");
  db::Statement insert(state_->db, sql::kInsertObject);
  if (insert.bind(1, sha).bind(2, int64_t(bytes.size())).step()) transaction.inserted_row("objects", insert);
  insert.reset();  // SQLite commits no transaction while a statement is in progress
  transaction.commit();
  return sha;
}

std::string Archive::store_object(std::string_view text) {
  return store_object(std::as_bytes(std::span(text.data(), text.size())));
}

std::filesystem::path Archive::object_path(std::string_view sha256) const {
  if (!is_sha256_hex(sha256)) throw Error(ErrorCode::kBadValue, std::string(sha256), "not a sha256 object name");
  return state_->objects.path_of(sha256);
}

std::vector<std::byte> Archive::read_object(std::string_view sha256) const { return read_file(object_path(sha256)); }

int64_t Archive::add_artefact(const NewArtefact& a) {
  if (!is_sha256_hex(a.object_sha256) || !std::filesystem::exists(object_path(a.object_sha256)))
    throw Error(ErrorCode::kNotFound, a.object_sha256, "artefact object is not in the store (use store_object first)");
  if (!Json::accept(a.parameters_json)) throw Error(ErrorCode::kBadValue, a.kind, "artefact parameters are not JSON");
  StoreLock lock(*state_, LockKind::Shared);  // verify and rebuild see no half-done change
  JournalledTransaction transaction(state_->db, state_->journal, "artefact");
  db::Statement insert(state_->db, sql::kInsertArtefact);
  insert.bind(1, a.case_id).bind(2, a.kind).bind(3, a.object_sha256).bind(4, a.media_type).bind(5, a.inputs_hash);
  insert.bind(6, a.parameters_json).bind(7, kVersion).bind(8, utc_now());
  int64_t id = db::inserted_id(insert).value();
  transaction.inserted("artefacts", id);
  transaction.commit();
  return id;
}

std::optional<ArtefactRecord> Archive::find_artefact(int64_t case_id, std::string_view kind,
                                                     std::string_view inputs_hash) const {
  db::Statement query(state_->db, std::string(sql::kArtefactColumns) + sql::kFindArtefact);
  query.bind(1, case_id).bind(2, kind).bind(3, inputs_hash);
  if (!query.step()) return std::nullopt;
  return artefact_from(query);
}

std::vector<ArtefactRecord> Archive::artefacts(int64_t case_id) const {
  return std::move(artefacts(std::vector<int64_t>{case_id})[case_id]);
}

std::map<int64_t, std::vector<ArtefactRecord>> Archive::artefacts(const std::vector<int64_t>& case_ids) const {
  std::map<int64_t, std::vector<ArtefactRecord>> found;
  for (int64_t id : case_ids) found[id];
  db::for_each_row_with_ids(state_->db, std::string(sql::kArtefactColumns) + sql::kArtefactsOfCasesIn, sql::kInIdOrder,
                            case_ids,
                            [&](const db::Statement& row) { found[row.integer(1)].push_back(artefact_from(row)); });
  return found;
}

}  // namespace maxillo
