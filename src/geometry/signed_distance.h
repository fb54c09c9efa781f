#pragma once
// Signed distance to a closed, outward-oriented triangle surface (mm): negative inside.
// The sign comes from the angle-weighted pseudo-normal of the nearest feature (face, edge or
// vertex; Baerentzen & Aanaes 2005), which is correct at edges and corners, where the nearest
// face's own normal can point the wrong way.
#include <Eigen/Geometry>
#include <vector>

#include "geometry/aabb_tree.h"

namespace maxillo {

struct SignedDistance {
  bool found = false;                                // false: no surface within the search radius (value unknown)
  double distance = 0;                               // signed, mm; negative inside the closed surface
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // nearest surface point
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit pseudo-normal there (outward)
  int face = -1;
};

class DistanceField {
 public:
  // Keeps a reference to `mesh` (must outlive this object).
  explicit DistanceField(const TriangleMesh& mesh);

  const AabbTree& tree() const { return tree_; }
  const TriangleMesh& mesh() const { return tree_.mesh(); }

  // Signed distance of `p` (this mesh's frame) if the surface lies within max_distance mm.
  SignedDistance signed_distance(const Eigen::Vector3d& p, double max_distance) const;

 private:
  Eigen::Vector3d pseudo_normal(int face, TriangleFeature feature) const;

  AabbTree tree_;
  std::vector<Eigen::Vector3d> face_normals_;
  std::vector<Eigen::Vector3d> edge_normals_;    // 3 per face: AB, BC, CA
  std::vector<Eigen::Vector3d> vertex_normals_;  // angle weighted
};

}  // namespace maxillo
