#pragma once
// Sliding nodes squeezed between moved and unmoved bone. A sliding node's move along the bone's
// normal is imposed (boundary_conditions.h); where a tet joins such a node to three nodes held
// on unmoved bone (tissue between the moved maxilla and the pterygoid plates, or at the
// osteotomy's gap), the imposed move alone can flatten the tet or turn it inside out, whatever
// the free nodes do. The linear models do not notice; the non-linear FEM cannot pass that
// configuration and stops (issue 34: the cadaver with its hand-placed landmarks, at 72 % of a
// 6 mm advancement, three tets of three fixed corners and one sliding). Such tissue is not lying
// on the bone's outer surface but pinched between two bones, where in surgery it is torn or
// pushed aside: those sliding nodes are left free.
#include "softtissue/boundary_conditions.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

// Frees the sliding nodes of every tet that has no free corner and whose volume, with each
// corner moved by what its constraint imposes, falls below `smallest_volume_fraction` of its
// own. Returns how many nodes were freed.
int release_squeezed_sliding_nodes(const TetMesh& mesh, BoundaryConditions& bc, double smallest_volume_fraction = 0.1);

}  // namespace maxillo::softtissue
