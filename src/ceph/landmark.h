#pragma once
// Anatomical landmarks: a label and a position in the patient LPS frame (mm).
// Canonical labels (see docs/ARCHITECTURE.md): S, N, Or, Po, A, B, ANS, PNS, Pog, Me, Gn, Go,
// Ar, U1 (upper incisor tip), L1 (lower incisor tip), U6R/U6L and L6R/L6L (first molar
// mesio-buccal cusps, patient right/left). Bilateral points carry an R/L suffix (OrR, PoL...).
// Cephalometry (cephalometric_analysis.h) also reads: Si (the source's maxillary point: lowest
// point of the maxillary sinus on a parallel to ANS-PNS), occlusal plane points U4/L4 or U5/L5
// (premolars, with U6/L6 the functional occlusal plane) or OccP/OccA (a traced occlusal line).
// On a 2D cephalogram bilateral points may be given without suffix (Go, U6...).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace maxillo {

struct Landmark {
  std::string label;
  Eigen::Vector3d position;  // LPS, mm
};

using LandmarkSet = std::vector<Landmark>;

// The position of the landmark with this label, if present.
std::optional<Eigen::Vector3d> find_landmark(const LandmarkSet& set, const std::string& label);

// The position of a landmark a computation cannot do without; Error(kBadValue, subject,
// "needs the landmark <label>") when it is missing.
Eigen::Vector3d require_landmark(const LandmarkSet& set, const std::string& label, const std::string& subject);

// A bilateral point as one: the mean of its R and L versions when both exist, else the
// unsuffixed label (a 2D cephalogram), else whichever side exists.
std::optional<Eigen::Vector3d> bilateral_mean(const LandmarkSet& set, const std::string& label);

// The bilateral landmarks' names without side (Or, Po, Go, Ar, Co, U6, L6, U5, L5, U4, L4).
bool is_bilateral_base(const std::string& label);
// "GoR" -> "Go" for a known bilateral landmark with an R/L suffix; nullopt otherwise (midline).
std::optional<std::string> bilateral_base(const std::string& label);

// SHA-256 of the labels and positions (to 1 µm) in order: what derivation keys use to name a
// landmark set.
std::string landmarks_hash(const LandmarkSet& set);

}  // namespace maxillo
