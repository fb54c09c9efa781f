#include "records/derivation.h"

#include "core/error.h"
#include "core/sha256.h"
#include "core/version.h"

namespace maxillo::records {

namespace {
std::string content_hash_of(const std::vector<std::string>& object_hashes) {
  Sha256 hash;
  for (const auto& sha : object_hashes) {
    hash.update(sha);
    hash.update("\n");
  }
  return hash.hex_digest();
}
}  // namespace

std::string series_content_hash(const Archive& archive, int64_t series) {
  return content_hash_of(archive.series_object_hashes(series));
}

std::vector<std::string> series_content_hashes(const Archive& archive, const std::vector<int64_t>& series) {
  const auto objects = archive.series_object_hashes(series);
  std::vector<std::string> hashes;
  for (int64_t id : series) hashes.push_back(content_hash_of(objects.at(id)));
  return hashes;
}

std::string derivation_key(const std::vector<std::string>& input_hashes, const Json& parameters) {
  Sha256 hash;
  for (const auto& input : input_hashes) {
    hash.update(input);
    hash.update("\n");
  }
  hash.update(parameters.dump());  // nlohmann::json orders object keys: the dump is canonical
  hash.update("\n");
  hash.update(kVersion);
  return hash.hex_digest();
}

int64_t primary_series(const CaseContents& contents) {
  for (const auto& entry : contents.series)
    if (entry.role == "preop") return entry.series.id;
  for (const auto& entry : contents.series)
    if (entry.series.modality == "CT") return entry.series.id;
  throw Error(ErrorCode::kNotFound, "case " + std::to_string(contents.record.id), "the case has no CT series");
}

std::string study_date_of(const CaseContents& contents, int64_t series) {
  for (const auto& entry : contents.series)
    if (entry.series.id == series)
      for (const auto& study : contents.studies)
        if (study.id == entry.series.study) return study.date;
  return "";
}

}  // namespace maxillo::records
