#pragma once
// Mandible landmarks that depend on the ramus outline (reference anatomy: the rami do not move
// with the mandibular protrusion knob, which stretches the body in front of them).
#include <array>

#include "sample/phantom_dentition.h"

namespace maxillo::sample {

// Ramus outline in the (a, z) plane: [0] is gonion, [2] the posterior border's most posterior
// point below the condyle.
std::array<Vector2d, 11> ramus_outline(const PhantomDesign& design);
// |x| of the left ramus's mid-plane at height z (the right one is its mirror image): the plate
// leans outwards from the angle up to the condyle.
double ramus_mid_plane_x(double z);
Vector3d gonion(const PhantomDesign& design, Side side);

}  // namespace maxillo::sample
