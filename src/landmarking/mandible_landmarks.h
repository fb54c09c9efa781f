#pragma once
// The landmarks of the mandibular ramus, one side at a time (side = +1 left, -1 right), in the
// head frame of midline_landmarks.h, read on the ramus seen from the side: the bone connected
// to the gonial angle (the ramus and condyle, apart from the skull at the joint space)
// projected onto the sagittal plane.
//
//   Go  gonion: where the bisector of the angle between the ramus tangent (the line from Ar
//       touching the posterior border near the angle) and the mandibular plane (the line from Me
//       touching the lower border near the angle) meets the angle's outline
//   Ar  articulare: on a lateral cephalogram, where the posterior border of the condylar
//       process crosses the shadow of the cranial base; read in 3D as the border's point at the
//       height of the cranial base's underside at the midline at the same depth
#include "landmarking/head_volume.h"
#include "landmarking/rule_finding.h"

namespace maxillo::landmarking {

// Needs Me (found or expected) in `found`; adds Go and Ar of the side.
void find_ramus_landmarks(const HeadVolume& v, double scale, int side, Findings& found);

}  // namespace maxillo::landmarking
