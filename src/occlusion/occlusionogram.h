#pragma once
// The occlusionogram (thesis ch. 7, Fig. 4c): per-vertex signed distance of each arch to the
// opposing one, and the contact regions closer than a threshold (1 mm in the source), counted
// per tooth. Teeth are the connected components of each arch mesh (the scanned arches are
// separate closed shells per tooth); a fused arch is one "tooth".
#include <Eigen/Geometry>
#include <vector>

#include "geometry/signed_distance.h"

namespace maxillo::occlusion {

struct OcclusionogramOptions {
  double contact_threshold_mm = 1.0;  // a vertex is in contact below this signed distance
  double max_distance_mm = 5.0;       // distances are searched up to here, larger ones reported as this
};

struct ToothContacts {
  int component = 0;            // connected component index within the arch (ordered by lowest vertex index)
  int vertices = 0;             // vertices of the tooth
  int contact_vertices = 0;     // vertices below the threshold
  double contact_area_mm2 = 0;  // each face contributes a third of its area per contact vertex
  double min_distance_mm = 0;   // signed; negative = penetration
};

struct ArchDistances {
  std::vector<double> distance_mm;   // per vertex, signed (negative inside the other arch), capped
  std::vector<int> tooth_of_vertex;  // component index per vertex
  std::vector<ToothContacts> teeth;
  double contact_area_mm2 = 0;
  int contact_vertices = 0;
};

struct Occlusionogram {
  ArchDistances upper, lower;
};

// `upper_pose`: upper file coordinates -> lower file coordinates.
Occlusionogram compute_occlusionogram(const DistanceField& upper, const DistanceField& lower,
                                      const Eigen::Isometry3d& upper_pose, const OcclusionogramOptions& options = {});

// Connected components of the faces (shared vertices), one label per vertex (-1: unused vertex).
std::vector<int> vertex_components(const TriangleMesh& mesh, int* component_count);

}  // namespace maxillo::occlusion
