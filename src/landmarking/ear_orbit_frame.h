#pragma once
// The provisional head frame when the scan holds no cranial base to take it from. The detector
// sets its first frame on sella and nasion (landmark_detection.cpp); a cone-beam field cut
// just above the orbits shows neither, or shows the fossa without the brain above it. Frankfort
// then comes first, from what such a field always holds:
//
//  1. the two ear canals, sought across each lateral third of the head where the midsagittal
//     plane puts them (the side is known, the height and depth are not): the head's size (the
//     porions lie 123.5 mm apart at scale 1) and the back end of Frankfort;
//  2. the orbits' lower rims, sought where each pitch within +-30 degrees would put them in
//     front of the porions; the pitch whose rims are found closest to where it put them wins
//     (two rims before one: an orbit may lie at the field's edge), and the line from the
//     porions' midpoint to the orbitales' midpoint is Frankfort.
//
// The frame's origin is then where sella lies over Frankfort in the landmark template.
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "core/volume.h"
#include "imaging/grey_calibration.h"

namespace maxillo::landmarking {

// The skull's extent in the midsagittal section of the sagittal frame (mm): its most anterior
// bone, its most posterior, its top, and whether the field goes on above that top (the vertex
// was scanned) or ends there (a cone-beam field cut through the skull).
struct MidlineExtent {
  double y_front = 0, y_back = 0, z_top = 0;
  bool vertex_scanned = true;
};

struct EarOrbitFrame {
  Eigen::Isometry3d frame;  // frame -> LPS: x the midsagittal normal, Frankfort horizontal
  double scale = 1;         // from the porions' distance
};

// `sagittal`: frame -> LPS whose x is the midsagittal normal and whose pitch is the scan's.
// nullopt, with the reason in `why`, when either ear canal, or both orbital rims, are not found.
std::optional<EarOrbitFrame> frame_from_ears_and_orbits(const Volume& ct, const GreyCalibration& grey,
                                                        const Eigen::Isometry3d& sagittal, const MidlineExtent& extent,
                                                        std::string& why);

}  // namespace maxillo::landmarking
