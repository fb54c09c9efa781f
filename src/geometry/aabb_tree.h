#pragma once
// A bounding volume hierarchy of axis-aligned boxes over the triangles of one mesh, in the
// mesh's own frame (mm). Queries against a second tree take the rigid transform that places
// the other mesh in this mesh's frame, so a moving arch never has its tree rebuilt.
#include <Eigen/Geometry>
#include <utility>
#include <vector>

#include "core/triangle_mesh.h"
#include "geometry/triangle_geometry.h"

namespace maxillo {

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-1e300);
  void extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Aabb& b) {
    min = min.cwiseMin(b.min);
    max = max.cwiseMax(b.max);
  }
};

// Face indices (this mesh, other mesh).
using FacePair = std::pair<int, int>;

struct NearestPoint {
  int face = -1;  // -1: nothing within the search radius
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  TriangleFeature feature = TriangleFeature::Face;
  double distance = 0;  // unsigned, mm
};

class AabbTree {
 public:
  // Keeps a reference: `mesh` must outlive the tree and stay unchanged.
  explicit AabbTree(const TriangleMesh& mesh);

  const TriangleMesh& mesh() const { return *mesh_; }
  Triangle triangle(int face) const;

  // Every pair of faces whose closed triangles share a point, `other` placed by other_to_this.
  // Sorted, so the answer is deterministic. Exact up to the rounding of the transform.
  std::vector<FacePair> intersecting_faces(const AabbTree& other, const Eigen::Isometry3d& other_to_this) const;

  // Faces of this mesh and of `other` whose leaf boxes come within `gap` mm of a leaf box of
  // the other mesh: a superset of the faces within `gap` of the other surface. Flags per face.
  std::pair<std::vector<char>, std::vector<char>> faces_near(const AabbTree& other,
                                                             const Eigen::Isometry3d& other_to_this, double gap) const;

  // The surface point nearest to `p` (this mesh's frame) if one lies within max_distance mm.
  NearestPoint nearest(const Eigen::Vector3d& p, double max_distance) const;

 private:
  struct Node {
    Aabb box;
    int left = -1, right = -1;  // children; -1 on leaves
    int first = 0, count = 0;   // leaves: range in order_
  };
  int build(int first, int count, const std::vector<Eigen::Vector3d>& centroids);
  template <typename Visit>
  void traverse_pairs(const AabbTree& other, const Eigen::Isometry3d& other_to_this, double gap, Visit&& visit) const;

  const TriangleMesh* mesh_;
  std::vector<Node> nodes_;
  std::vector<int> order_;  // face indices grouped by leaf
};

}  // namespace maxillo
