#pragma once
// Boundary conditions of a face model from the bone it lies on (thesis ch. 6: join points).
// A node touches bone when a voxel of a bone segment lies within touch_mm of it; it then
// follows that segment's rigid move (prescribed) or, when the segment does not move, stays put
// (fixed). Nodes on a cut plane of the region are fixed too: the tissue beyond is not
// modelled and is taken as unmoved. Every other node is free.
#include <Eigen/Geometry>
#include <map>
#include <vector>

#include "core/volume.h"
#include "softtissue/boundary_conditions.h"
#include "softtissue/face_region.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct AttachmentOptions {
  double touch_mm = 1.5;                // how close bone must be for a node to be joined to it
  double cut_plane_tolerance_mm = 1.0;  // nodes this close to a region plane are on the cut
};

struct Attachment {
  BoundaryConditions bc;
  std::vector<uint8_t> segment;  // per node: the bone segment it is joined to (0 = none)
};

// `segments` labels bone segments (0 = no bone); `moves` gives the rigid move of each moved
// segment (pre-op -> planned, LPS mm); segments absent from `moves` stay where they are.
Attachment attach_to_bone(const TetMesh& mesh, const LabelVolume& segments,
                          const std::map<uint8_t, Eigen::Isometry3d>& moves, const std::vector<RegionPlane>& cut_planes,
                          const AttachmentOptions& options = {});

}  // namespace maxillo::softtissue
