#pragma once
// Boundary conditions of a face model from the bone it lies on (thesis ch. 6: join points).
// A node touches bone when a voxel of a bone segment lies within touch_mm of it; it then
// follows that segment's rigid move (prescribed) or, when the segment does not move, stays put
// (fixed); with MovedBoneContact::kSliding a node on a moved segment slides on its surface instead
// (boundary_conditions.h), its normal the direction away from the bone voxels within touch_mm +
// 1 mm. Nodes where the region's shape cuts through tissue are fixed too (RegionShape::on_cut):
// the tissue beyond is not modelled and is taken as unmoved. Every other node is free.
//
// With outer_surface_only (off by default, see below), a moved segment carries only the tissue on
// its outer surface (its periosteum): a node inside
// one of the bone's cavities (a sinus, the nasal cavity seen from its floor or walls) is left
// free (issue 34): in surgery the septum and the nasal mucosa are freed from the maxilla, and
// tissue that bone closes around does not pull on the face. Inside means: three of five rays
// cast from the node away from the bone it touches (the outward direction and four tilted 30
// degrees about it) meet bone again within cavity_reach_mm. On the outer surface (the lip's side
// of the alveolus, the cheek's side of the maxilla) the rays leave through the face. A piece of
// the mesh left with no constrained node follows its bone after all. Off by default: on the
// cadaver head it moved no profile point by 0.01 of the advancement, and the lining it freed in
// the nasal cavity, between the moved maxilla and the fixed bone above the cut, bulged 10.2 mm
// for a 6 mm advancement (docs/ARCHITECTURE.md, "Soft tissue realism").
#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/volume.h"
#include "softtissue/boundary_conditions.h"
#include "softtissue/face_region.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

// How tissue touching a moved segment follows it.
enum class MovedBoneContact {
  kTied,               // it moves with the bone (the thesis' join points)
  kSliding,            // its move along the bone's outward normal is the bone's; across it, it slides
  kSlidingInCavities,  // sliding inside the bone's cavities (inside_bone_cavity), tied on its outer surface
};

// "tied", "sliding" or "sliding-in-cavities", and back (std::nullopt for another name); all three.
const char* contact_name(MovedBoneContact contact);
std::optional<MovedBoneContact> contact_named(std::string_view name);
std::vector<std::string> contact_names();

struct AttachmentOptions {
  double touch_mm = 1.5;                // how close bone must be for a node to be joined to it
  double cut_plane_tolerance_mm = 1.0;  // nodes this close to a region plane are on the cut
  bool outer_surface_only = false;      // moved segments carry the tissue on their outer surface only
  double cavity_reach_mm = 60;          // bone this far along a ray from a node closes a cavity around it
  MovedBoneContact moved_bone_contact = MovedBoneContact::kSliding;
};

struct Attachment {
  BoundaryConditions bc;
  std::vector<uint8_t> segment;  // per node: the bone segment it is joined to (0 = none)
  int inner_nodes = 0;           // nodes touching a moved segment inside its cavities, left free
  int uncarried_nodes = 0;       // nodes touching a moved segment that the caller said it does not carry
};

// Whether a node at `p`, touching the bone of `segments` around it, lies inside a cavity of
// the bone (the rule above). `segments`: any non-zero label is bone.
bool inside_bone_cavity(const LabelVolume& segments, const Eigen::Vector3d& p, const AttachmentOptions& options);

// `segments` labels bone segments (0 = no bone); `moves` gives the rigid move of each moved
// segment (pre-op -> planned, LPS mm); segments absent from `moves` stay where they are.
// `not_carried`: per node (or empty), non-zero where no moved segment carries the tissue: such a
// node touching moved bone is left free (touching unmoved bone it is still fixed). The case
// workflow passes the cartilaginous nose (casework/softtissue/nasal_cartilage.h): it follows
// the tissue, not the bone. A piece of the mesh that nothing else anchors follows its bone
// after all.
Attachment attach_to_bone(const TetMesh& mesh, const LabelVolume& segments,
                          const std::map<uint8_t, Eigen::Isometry3d>& moves, const RegionShape& region,
                          const AttachmentOptions& options = {}, const std::vector<uint8_t>& not_carried = {});

}  // namespace maxillo::softtissue
