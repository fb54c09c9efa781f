#pragma once
// Mandible landmarks that depend on the ramus outline (reference anatomy: the rami do not move
// with the mandibular protrusion knob, which stretches the body in front of them).
#include <array>

#include "sample/phantom_dentition.h"

namespace maxillo::sample {

// Ramus outline in the (a, z) plane: [0] is gonion, [2] articulare.
std::array<Vector2d, 11> ramus_outline(const PhantomDesign& design);
Vector3d gonion(const PhantomDesign& design, Side side);
Vector3d articulare(const PhantomDesign& design, Side side);

}  // namespace maxillo::sample
