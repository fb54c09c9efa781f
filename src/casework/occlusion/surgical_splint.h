#pragma once
// A surgical splint (issue 6 item 6) as a closed surface, with the checks that make it usable:
// watertight, one piece, touching both arches without penetrating them, at least the minimum
// thickness where no tooth is. The solid comes from occlusion/splint_field.h; its zero
// iso-surface is extracted by marching cubes (flying edges) without smoothing or decimation,
// which would move the imprints into the teeth.
#include <Eigen/Geometry>

#include "core/triangle_mesh.h"
#include "occlusion/splint_field.h"

namespace maxillo::casework {

struct SplintReport {
  bool watertight = false;  // every edge shared by two faces, consistently oriented
  int components = 0;
  double volume_mm3 = 0;
  int64_t triangles = 0;
  double thickness_mm = 0;    // thinnest of the sampled tooth-free columns (ray through the wafer)
  int thickness_columns = 0;  // how many columns were sampled
  // Smallest distance from a splint vertex to each arch's surface (mm): at most
  // clearance + one voxel where the imprint fits the tooth.
  double min_distance_upper_mm = 0, min_distance_lower_mm = 0;
  // Splint triangles intersecting each arch's triangles (0: no penetration).
  int64_t intersecting_pairs_upper = 0, intersecting_pairs_lower = 0;
  double seconds = 0;
};

struct Splint {
  TriangleMesh mesh;  // lower arch frame, mm, outward normals
  occlusion::OcclusalPlane plane;
  SplintReport report;
};

// The splint between the arches at their final occlusion (upper placed by upper_pose).
// Throws Error(kProcessing) when the arches are not in occlusion or no closed surface results.
Splint make_splint(const DistanceField& upper, const DistanceField& lower, const Eigen::Isometry3d& upper_pose,
                   const occlusion::SplintOptions& options = {});

// Total length of `mesh`'s interior along the line through `point` with unit `direction` (the
// ray is cast both ways; the mesh must be closed). Brute force: for a few columns.
double thickness_along(const TriangleMesh& mesh, const Eigen::Vector3d& point, const Eigen::Vector3d& direction);

}  // namespace maxillo::casework
