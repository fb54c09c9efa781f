#pragma once
// Skin surface that is no skin: where the mouth is open, a CT's outer surface runs over the
// exposed crowns of the teeth (and, after an injury or at a scan's edge, over bare bone). The soft
// tissue model holds no node there, so the mapping onto the skin gave those vertices the move of
// the nearest tissue or none, and the surface tore between the crowns and the lips attached to
// them (the cadaver head: 9.4 mm per mm at the upper incisors for a 6 mm advancement, issue 34).
// A vertex on exposed bone moves with its bone segment instead.
//
// A vertex lies on exposed bone when bone of a segment lies within 2 mm under it (inwards along
// its normal, every 0.25 mm): a crown's surface in air shows as a film of soft tissue's grey
// values (a voxel's worth of enamel and air averaged), and tissue that thin over bone moves with
// the bone anyway. The face's skin lies on thicker tissue (over the nasal bones about 3 mm, the
// lips and cheeks 10 mm and more).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "casework/plan/planned_case.h"
#include "core/triangle_mesh.h"
#include "core/volume.h"

namespace maxillo::casework {

// Per skin vertex, the bone segment (planning::Segment) it lies on, 0 where it lies on soft tissue.
// `skin`: closed and outward-oriented.
std::vector<uint8_t> exposed_bone_segments(const TriangleMesh& skin, const LabelVolume& segments);

// Sets the displacement of each vertex on exposed bone to its segment's move (zero for a segment
// the plan does not move).
void move_exposed_bone(const TriangleMesh& skin, const std::vector<uint8_t>& segment_of_vertex,
                       const SegmentMoves& moves, Eigen::MatrixX3d& displacement);

}  // namespace maxillo::casework
