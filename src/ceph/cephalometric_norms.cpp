#include "ceph/cephalometric_norms.h"

#include <cassert>
#include <cmath>

namespace maxillo::ceph {

std::optional<Norm> norm_for(std::string_view id, Sex sex) {
  if (id == "SNA") return Norm{82, 3.5, "Steiner 1953"};
  if (id == "SNB") return Norm{80, 3, "Steiner 1953"};
  if (id == "ANB") return Norm{2, 2.5, "Steiner 1953"};
  if (id == "Wits") {
    if (sex == Sex::kMale) return Norm{-1, 1.78, "Jacobson 1975 (male)"};
    return Norm{0, 1.77, sex == Sex::kFemale ? "Jacobson 1975 (female)" : "Jacobson 1975 (female; sex unknown)"};
  }
  return std::nullopt;
}

Deviation deviation_of(double value, const Norm& norm) {
  assert(norm.sd > 0 && "a norm needs a positive SD");
  double z = std::abs(value - norm.mean) / norm.sd;
  if (z > 2) return Deviation::kBeyondTwoSd;
  if (z > 1) return Deviation::kBeyondOneSd;
  return Deviation::kWithinOneSd;
}

std::string_view deviation_name(Deviation deviation) {
  switch (deviation) {
    case Deviation::kNoNorm: return "";
    case Deviation::kWithinOneSd: return "within 1 SD";
    case Deviation::kBeyondOneSd: return "> 1 SD";
    case Deviation::kBeyondTwoSd: return "> 2 SD";
  }
  return "";
}

}  // namespace maxillo::ceph
