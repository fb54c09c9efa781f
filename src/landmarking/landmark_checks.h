#pragma once
// The checks every detected landmark set goes through, as the issue of automatic landmarks asks:
//   - bilateral pairs mirror each other about the midsagittal plane (within 4 mm);
//   - the order the anatomy imposes (N anterior to S, ANS anterior to PNS, Me below Pog, B above
//     Pog, A below ANS, Or in front of Po, the soft-tissue points in front of their bone);
//   - distances and angles within published adult ranges, widened (S-N, ANS-Me, ANS-PNS, SNA,
//     SNB, the gonial angle);
//   - the same point found again from a second start (the rule run from a window shifted by a
//     few millimetres): it must come back within 1 mm.
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

}  // namespace maxillo::landmarking
