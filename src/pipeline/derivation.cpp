#include "pipeline/derivation.h"

#include "core/error.h"
#include "core/sha256.h"
#include "core/version.h"

namespace maxillo::pipeline {

std::string series_content_hash(const Archive& archive, int64_t series) {
  Sha256 hash;
  for (const auto& instance : archive.instances(series)) {
    hash.update(instance.object_sha256);
    hash.update("\n");
  }
  return hash.hex_digest();
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

}  // namespace maxillo::pipeline
