#pragma once
// The cephalometric analysis of one landmark set: every measurement of the source's chapter 5
// (SNA, SNB, ANB, Wits, the nasion-frame positions of ANS, PNS and Si, the palatal plane angle
// alpha) with its norm and deviation flag. A measurement whose landmarks are missing is "not
// available" with the reason; the others are still computed.
//
// Occlusal line of the Wits appraisal, first that applies:
//   1. OccP -> OccA: occlusal plane points traced explicitly (posterior, anterior);
//   2. functional occlusal plane: midpoint of U6/L6 (first molars) -> midpoint of U4/L4 (first
//      premolars), or of U5/L5 (second premolars);
//   3. occlusal plane through the molar overlap (U6/L6) and the incisor overlap (U1/L1 midpoint)
//      when no premolar points exist (the conventional occlusal plane). The measurement's note
//      says which one was used.
// In 3D, bilateral points (U6R/U6L ...) are averaged before projection (sagittal_projection.h).
#include <optional>
#include <string>
#include <vector>

#include "ceph/cephalometric_norms.h"
#include "ceph/sagittal_projection.h"

namespace maxillo::ceph {

struct Measurement {
  std::string id;                    // "SNA", "SNB", "ANB", "Wits", "ANS_X", "ANS_Y", "PNS_X", ..., "Si_Y", "alpha"
  std::string name;                  // human-readable
  std::string unit;                  // "deg" or "mm"
  std::optional<double> value;       // nullopt = not available
  std::string not_available_reason;  // e.g. "missing landmark(s): B"
  std::optional<Norm> norm;
  Deviation deviation = Deviation::kNoNorm;
  std::string note;  // e.g. which occlusal line the Wits appraisal used
};

struct CephalometricAnalysis {
  std::string frame;                      // SagittalLandmarks::frame
  std::vector<Measurement> measurements;  // always every id, in the order listed above
  const Measurement* find(const std::string& id) const;
  std::optional<double> value(const std::string& id) const;
};

// The measurement ids in report order.
const std::vector<std::string>& measurement_ids();

CephalometricAnalysis analyse(const SagittalLandmarks& landmarks, Sex sex = Sex::kUnknown);

}  // namespace maxillo::ceph
