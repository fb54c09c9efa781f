#pragma once
// Population norms for the cephalometric measurements and the deviation flags derived from them.
//
// Norms (mean +- SD), adults; used to flag values, not to diagnose:
//   SNA 82 +- 3.5 deg, SNB 80 +- 3 deg, ANB 2 +- 2.5 deg: Steiner's means (1953) with SDs typical
//     of published adult samples (rounded).
//   Wits appraisal (Jacobson 1975): females 0 +- 1.77 mm, males -1 +- 1.78 mm; sex unknown uses the
//     female values (0 mm is the source's "normal sagittal relationship").
//   The nasion-frame coordinates and alpha have no norm: the source uses them for changes over time.
#include <optional>
#include <string>
#include <string_view>

namespace maxillo::ceph {

enum class Sex { kUnknown, kFemale, kMale };

struct Norm {
  double mean = 0;
  double sd = 1;       // > 0
  std::string source;  // "Steiner 1953", "Jacobson 1975 (female)", ...
};

// The norm of a measurement id ("SNA", "SNB", "ANB", "Wits"); nullopt when there is none.
std::optional<Norm> norm_for(std::string_view measurement_id, Sex sex);

enum class Deviation { kNoNorm, kWithinOneSd, kBeyondOneSd, kBeyondTwoSd };
// |value - mean| <= 1 SD, in (1, 2] SD, or > 2 SD.
Deviation deviation_of(double value, const Norm& norm);
std::string_view deviation_name(Deviation deviation);  // "", "within 1 SD", "> 1 SD", "> 2 SD"

}  // namespace maxillo::ceph
