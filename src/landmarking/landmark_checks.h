#pragma once
// The checks every detected landmark set goes through, as the issue of automatic landmarks asks:
//   - bilateral pairs mirror each other about the midsagittal plane (within 5 mm; the lower first
//     molars about the mandible's own midline, which a deviated chin carries to one side);
//   - the order the anatomy imposes (N anterior to S, ANS anterior to PNS, Me below Pog, B above
//     Pog, A below ANS, Or in front of Po, the soft-tissue points in front of their bone);
//   - distances and angles within published adult ranges, widened (S-N, ANS-Me, ANS-PNS, SNA,
//     SNB, the gonial angle);
//   - the same point found again from a second start (every rule but sella's run again with its search
//     window placed 4 % farther from sella): it must come back within 1.5 mm.
// A landmark that fails a check is flagged: not used for planning unless a person confirms it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace maxillo::landmarking {

struct CheckOutcome {
  std::string name;  // "mirror", "order: N anterior to S", "range: S-N", "second start"
  bool passed = true;
  std::string detail;  // the measured value against the limit
};

// Points in the head frame (x left, y posterior, z superior; absent labels missing).
using FramePoints = std::map<std::string, Eigen::Vector3d>;

// The checks of each label (only the checks whose points are present are run).
std::map<std::string, std::vector<CheckOutcome>> check_landmarks(const FramePoints& points, double scale);

// How far a second start may find a point from the first: a rule whose answer depends on where
// its window starts by more than this has found no definite point.
inline constexpr double kSecondStartToleranceMm = 1.5;
// The second start's check of a point found at `first`: `again` is where the second start found
// it (nullopt: not found again).
CheckOutcome second_start_check(const Eigen::Vector3d& first, const std::optional<Eigen::Vector3d>& again);

}  // namespace maxillo::landmarking
