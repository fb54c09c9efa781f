#include "casework/landmarks/case_orientation.h"

#include "core/error.h"
#include "core/log.h"
#include "core/utc_time.h"
#include "imaging/head_orientation.h"
#include "records/archived_series.h"
#include "records/derivation.h"

namespace maxillo::casework {
namespace {

struct CaseCt {
  int64_t series = 0;
  std::string content_hash;
};

CaseCt case_ct(const Archive& archive, int64_t case_id) {
  CaseCt ct;
  ct.series = records::primary_series(archive.case_contents(case_id));
  ct.content_hash = records::series_content_hash(archive, ct.series);
  return ct;
}

// The record of this CT content: stored, or the check run now and stored.
records::OrientationRecord orientation_of(Archive& archive, int64_t case_id, const CaseCt& checked, const Volume* ct) {
  if (auto stored = records::stored_orientation(archive, case_id, checked.content_hash)) return *stored;
  const Volume loaded = ct ? Volume{} : records::load_archived_series(archive, checked.series);
  const auto record = records::orientation_record(checked.series, check_head_orientation(ct ? *ct : loaded));
  records::store_orientation(archive, case_id, checked.content_hash, record);
  if (record.contradicts_header)
    log::warning("case:", case_id, ": ", record.finding);
  else
    log::debug("case:", case_id, ": ", record.finding);
  return record;
}

}  // namespace

records::OrientationRecord case_orientation(Archive& archive, int64_t case_id, const Volume* ct) {
  return orientation_of(archive, case_id, case_ct(archive, case_id), ct);
}

void require_trusted_orientation(Archive& archive, int64_t case_id, const std::string& what) {
  const auto record = case_orientation(archive, case_id);
  if (record.trusted()) return;
  throw Error(ErrorCode::kBadValue, "case:" + std::to_string(case_id),
              what + " refused: " + record.finding +
                  ". Check the scan (and its conversion); if the volume is right as it is, confirm it with `maxillo "
                  "orientation case:" +
                  std::to_string(case_id) + " --confirm`; if an axis was flipped, have it undone with `--reorient`");
}

records::OrientationRecord confirm_orientation(Archive& archive, int64_t case_id) {
  const CaseCt checked = case_ct(archive, case_id);  // the series' content hashed once
  auto record = orientation_of(archive, case_id, checked, nullptr);
  record.confirmed_at = utc_now();
  records::store_orientation(archive, case_id, checked.content_hash, record);
  return record;
}

}  // namespace maxillo::casework
