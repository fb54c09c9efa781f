#pragma once
// The first molars' landmarks, one side at a time (side = +1 left, -1 right), in the head frame
// of midline_landmarks.h:
//
//   U6, L6  the mesio-buccal cusp tip of the upper and lower first molar
//
// In a box of enamel beside the arch: the occlusal line, where the upper and lower crowns meet
// (their section per height narrows there, or shows a gap); along the arch, the crowns one after
// the other, split where they narrow to a contact; the first molar the crown of a molar's length
// and width nearest the template; its mesio-buccal cusp tip placed from the crown's outline (a
// quarter of its length and of its width in from its mesial and buccal faces), since at a
// scan's resolution cusps in occlusion merge with the opposing crowns. docs/ARCHITECTURE.md
// ("Automatic landmarks") has the figures.
#include "landmarking/head_volume.h"
#include "landmarking/rule_finding.h"

namespace maxillo::landmarking {

// Sets found["U6R"] and found["L6R"] (side -1) or the L pair (side +1): the cusp tip, or absent
// with the reason (no crowns meeting, no crown of a first molar's size, outside the scan).
void find_first_molars(const HeadVolume& v, double scale, int side, Findings& found);

}  // namespace maxillo::landmarking
