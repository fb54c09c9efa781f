#pragma once
// Where the maxillary sinuses lie on a label volume, and their air when the scan shows them open
// into the nasal cavity.
//
// The distractors are placed from the sinus air (distractor_checks.h), which the label volume
// holds as closed air (enclosed_air.h). A sinus whose medial wall or ostium is wider than the
// scan's voxels shows no closed air: at the cadaver head's 2 mm slices both sinuses join the
// nasal airway, which reaches the outside, so their air is the outside's. Such a sinus is still
// told from the nose by where its air lies and what surrounds it:
//   - in the sinus box (below): between the palatal plane and the orbitales, from behind PNS to
//     in front of ANS;
//   - farther from the midsagittal plane than the nasal cavity reaches (kNasalHalfWidthMm, the
//     lateral nasal wall of an adult at the inferior turbinate; the sinus lies lateral to it);
//   - walled: tissue (anything but the outside's air; a wall thinner than the voxels reads as
//     soft tissue) within kWallReachMm in front, where the distractor enters, and on three at
//     least of the other four sides: laterally, posteriorly, above (the orbital floor) and below
//     (the alveolar process). Air in front of the face has nothing in front of it; air beside
//     the cheek nothing lateral to it or below it.
// The largest face-connected region of such air on each side is that side's sinus.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ceph/landmark.h"
#include "core/volume.h"
#include "planning/anatomical_moves.h"
#include "planning/distraction_vectors.h"

namespace maxillo::planning {

struct AnatomyLabels;

inline constexpr double kNasalHalfWidthMm = 15;
inline constexpr double kWallReachMm = 30;
inline constexpr double kMinEnclosedSinusCm3 = 2;  // less closed air on a side: the sinus is sought open

struct Interval {
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  bool contains(double value) const { return value >= low && value <= high; }
  bool bounded() const {
    return low > -std::numeric_limits<double>::infinity() && high < std::numeric_limits<double>::infinity();
  }
};

// Heights (along frame.superior) from 5 mm below the palatal plane to the orbitales, and depths
// (along frame.anterior) from 5 mm behind PNS to 5 mm in front of ANS. Unbounded where those
// landmarks are missing. On a real CT the closed air also holds the pharynx, the mastoid air
// cells and the ear canals, all behind PNS and some at the sinus' height.
struct SinusBox {
  Interval height, depth;
  bool bounded() const { return height.bounded() && depth.bounded(); }
  // Whether `p` (LPS) lies in the box on `side` of the midsagittal plane through frame.origin.
  bool contains(const Eigen::Vector3d& p, const PlanningFrame& frame, Side side) const;
};
SinusBox sinus_box(const PlanningFrame& frame, const LandmarkSet& landmarks);

// How each side's sinus air was found.
struct SinusAirReading {
  std::vector<std::string> notes;  // one per side whose sinus was taken open to the nose
};

// `labels` with each side's open sinus air (above) relabelled anatomy.sinus_air[0], for a side
// with less than kMinEnclosedSinusCm3 of closed air in its box. Labels `open_air` are the
// outside's air. Unchanged without the box's landmarks (ANS, PNS, an orbitale).
LabelVolume with_open_sinus_air(const LabelVolume& labels, const PlanningFrame& frame, const AnatomyLabels& anatomy,
                                const LandmarkSet& landmarks, SinusAirReading& reading);

}  // namespace maxillo::planning
