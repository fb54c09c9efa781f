#pragma once
// The orientation check of a case's CT (imaging/head_orientation.h) as the archive keeps it:
// one record per CT content (the series' content hash is its key), holding what the anatomy
// said and, when a person has looked at the volume and confirmed it as it is, when. A header
// that contradicts the anatomy makes planning and prediction refuse the case until then.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "archive/archive.h"
#include "core/json.h"
#include "imaging/head_orientation.h"

namespace maxillo::records {

struct OrientationRecord {
  static constexpr int kFormatVersion = 1;
  int64_t series = 0;
  std::string verdict;  // "agrees", "contradicts", "partly confirmed", "undetermined"
  std::string finding;  // HeadOrientation::finding()
  Eigen::Vector3d imbalance{0, 0, 0};
  double teeth_cm3 = 0;
  bool contradicts_header = false;
  std::string confirmed_at;  // UTC ISO 8601 when a person confirmed the volume; empty until then

  // Planning may use the volume: the anatomy agrees, cannot tell, or a person confirmed it.
  bool trusted() const { return !contradicts_header || !confirmed_at.empty(); }
};

OrientationRecord orientation_record(int64_t series, const HeadOrientation& found);

Json to_json(const OrientationRecord& record);
// Strict: Error(kArchiveCorrupt) naming `source` and the key of a missing or bad field.
OrientationRecord read_orientation_record(const Json& json, const std::string& source);

// Kept under `series_hash` (derivation.h: series_content_hash); a later record of the same
// content (a confirmation) supersedes the earlier one.
void store_orientation(Archive& archive, int64_t case_id, const std::string& series_hash,
                       const OrientationRecord& record);
// The newest record for this content, if the check has run on it.
std::optional<OrientationRecord> stored_orientation(const Archive& archive, int64_t case_id,
                                                    const std::string& series_hash);
// The newest record of each case whatever the content (for `list cases` and `show`), read
// with a few queries for all of them; cases never checked are absent.
std::map<int64_t, OrientationRecord> latest_orientations(const Archive& archive, const std::vector<int64_t>& cases);
// What a listing shows of a case's record: "contradicts!", "confirmed", "agrees", ...; "-"
// when the check has not run.
std::string orientation_summary(const OrientationRecord* record);

}  // namespace maxillo::records
