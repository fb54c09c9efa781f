#pragma once
// Contacts between the two dental arches. The lower arch is fixed and defines the common frame;
// the upper arch is placed by `upper_pose` (upper file coordinates -> lower file coordinates,
// mm). Both meshes must be closed and outward-oriented for the penetration sign to hold.
#include <Eigen/Geometry>
#include <vector>

#include "geometry/signed_distance.h"

namespace maxillo::occlusion {

enum class ContactSide { UpperVertex, LowerVertex };

// One vertex of either arch that lies within the search band of the opposing surface.
// gap_mm > 0: clearance; < 0: the vertex is inside the other arch by -gap_mm.
// Moving the upper arch by a small displacement field u(x) changes the gap by
// direction . u(anchor): anchor is a point of the upper arch (lower frame) and direction is a
// unit vector (lower frame), so the motion engine can linearise contacts.
struct ArchContact {
  ContactSide side = ContactSide::UpperVertex;
  int vertex = -1;  // index in that arch's mesh
  double gap_mm = 0;
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
};

struct ContactState {
  std::vector<ArchContact> contacts;  // every vertex of both arches within the band, sorted
  double max_penetration_mm = 0;      // deepest vertex inside the other arch (0 if none)
};

// Vertices of both arches within `band_mm` of the other surface (deeper ones are found as long
// as they are within band_mm of the surface). Deterministic.
ContactState assess_contacts(const DistanceField& upper, const DistanceField& lower,
                             const Eigen::Isometry3d& upper_pose, double band_mm);

}  // namespace maxillo::occlusion
