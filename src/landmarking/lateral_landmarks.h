#pragma once
// The bilateral landmarks, one side at a time (side = +1 for the patient's left, x > 0; -1 for
// the right), in the head frame of midline_landmarks.h:
//
//   Po  porion (anatomical): the most superior point of the bony external acoustic meatus, at its
//       lateral opening
//   Or  orbitale: the lowest point of the inferior margin of the orbit
#include "landmarking/head_volume.h"
#include "landmarking/rule_finding.h"

namespace maxillo::landmarking {

// The ear canal is found as the air inside the temporal bone (bone close above and below)
// within `reach` (y, z: mm either side) of `expected` that opens at the bone's lateral surface
// (the middle ear and the mastoid cells lie deeper and stay closed); Po is the top of the canal
// where it leaves the bone.
//
// Where along the canal its top is read (kAtOpening for the landmark): at the axis 1.5 mm inside
// the opening, the axis fitted to the canal's cross-sections 3-15 mm inside; kCanalCentre: above
// the whole air region's centre, the rule the Frankfort frames are still built on. The two agree
// on a straight canal that stays apart from the middle ear; on an oblique one the centre lies off
// the opening's axis, and where the canal's air joins the middle ear's it moves by millimetres
// (the cadaver head turned by 12 degrees: 0.9 mm). The frames keep the centre because the rules
// read in them (gonion, orbitale, the incisors) move with a tilt of a fraction of a degree: moved
// onto the opening's axis, four landmark tests failed through the frame alone (issue #28).
enum class PorionAxis { kAtOpening, kCanalCentre };
// How far about the expected place the canal is sought (y, z), where the frame is known.
inline const Eigen::Vector2d kPorionReachMm(20, 16);
RuleFinding find_porion(const HeadVolume& v, const Eigen::Vector3d& expected, int side,
                        const Eigen::Vector2d& reach = kPorionReachMm, PorionAxis axis = PorionAxis::kAtOpening);

// Seen from the front, rays below the orbit end on the maxilla and zygoma while rays into the
// orbit's opening go deep: the rim's lower edge is where that depth jumps, and Or is the lowest
// point of the edge across the orbit's width, sought across 24 mm about the expected place.
// kWidening: where the edge's bottom does not rise on both sides within those (a head larger
// than its frame's size says), across 40 mm too, taken when it rises on both sides there. Only
// for the landmark read in the head frame: the frames' own searches keep the narrow one, as a
// wider search moves the cadaver head's split rims, and its Frankfort frame with them. The
// landmark's search also reads the rim 1 mm beyond its width, so that the width's ends are
// smoothed like the rest; the frames' searches keep their raw ends (BENCH-024's pitch search
// found the right rim only at its window's end, and read 1 mm wider took another).
enum class OrbitSearch { kNarrow, kWidening };
RuleFinding find_orbitale(const HeadVolume& v, const Eigen::Vector3d& expected, int side,
                          OrbitSearch search = OrbitSearch::kNarrow);

}  // namespace maxillo::landmarking
