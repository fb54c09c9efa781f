#pragma once
// A surface cut by a plane: the profile lines of a face (e.g. the mid-sagittal profile of the
// predicted and the actual skin, thesis ch. 8) or of a bone. Eigen only.
#include <Eigen/Core>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo {

// The mesh cut by the plane through `point` with normal `normal` (any length > 0), as polylines:
// the crossing points of the mesh's edges, chained through shared edges. A closed loop repeats its
// first point at the end; where the mesh has a border the line ends there. Loops of an
// outward-oriented closed mesh run counter-clockwise seen from the side the normal points to.
// Vertices exactly on the plane count as on its positive side, so a cut through vertices gives no
// doubled points. Empty when the plane misses the mesh. Polylines come longest first (by point
// count). Throws Error(BadValue) for a zero normal.
std::vector<std::vector<Eigen::Vector3d>> plane_section(const TriangleMesh& mesh, const Eigen::Vector3d& point,
                                                        const Eigen::Vector3d& normal);

}  // namespace maxillo
