#pragma once
// `maxillo nightly --claim`: one of many workers, on one machine or many, that share the
// nightly validation of an archive through its work queue (archive/work_queue.h) instead of
// a static --shard slice.
//
// Each worker offers every eligible case without a validation of its current inputs (the item
// "case:<id>:<inputs hash>", so a change of inputs is new work), then claims items one at a
// time under a lease that a heartbeat thread renews. A worker killed mid-case stops renewing:
// when its lease ends another worker claims the case. Workers wait while others hold leases,
// so the last one leaves only when every item is finished. A case is validated once per
// change of its inputs: a worker re-checks for a stored validation before it starts. Workers
// write no summary: `nightly --summary-only` writes the one summary after them.
#include <chrono>
#include <string>

#include "archive/archive.h"
#include "archive/work_queue.h"
#include "nightly/nightly.h"

namespace maxillo::nightly {

inline constexpr const char* kNightlyQueue = "nightly";

// "case:<id>:<inputs hash>" and back (nullopt for another form).
std::string nightly_work_item(int64_t case_id, const std::string& inputs_hash);
std::optional<std::pair<int64_t, std::string>> parse_nightly_work_item(const std::string& item);

NightlyReport run_nightly_worker(Archive& archive, const NightlyOptions& options);

// What the work queue says of a case the summary finds without a validation of its current
// inputs (`record`: its item, or null when no worker offered it), at `now` on the index's
// clock: failed (kFailed, with the worker's reason), or left (kNotValidated: being validated,
// its worker stopped before finishing it, or never claimed), with how to finish it.
NightlyCase unfinished_case(int64_t case_id, const WorkRecord* record, int64_t now);

}  // namespace maxillo::nightly
