#pragma once
// Articulare as the field defines it: on a lateral cephalogram, where the shadow of the condylar
// process's posterior border crosses the inferior contour of the cranial base. Read in 3D: where
// the posterior border, traced upwards, rises to the underside of the cranial base at the midline
// at the same depth (the underside read downwards from the sella's height through the base, at its
// half-maximum edge). The phantom's truth is the same construction on its parts
// (sample/phantom_landmarks.cpp).
//
// Its evidence says how well the crossing is defined: full where the base's underside is level
// (a small error in depth then barely moves the crossing's height), none where it slopes at 2.5
// mm per mm or more (a steep clivus, as in the real cadaver head); at most 0.8 where the border
// had to be extended to reach the base. The note names the slope and the extension.
#include "landmarking/head_volume.h"
#include "landmarking/profile.h"
#include "landmarking/rule_finding.h"

namespace maxillo::landmarking {

// `border`: the ramus's posterior border in the head frame, ascending heights, from below the
// condylar neck up (y: its depth, x: the middle of the bone there).
RuleFinding find_articulare(const HeadVolume& v, const Profile& border, double scale);

}  // namespace maxillo::landmarking
