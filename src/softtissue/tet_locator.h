#pragma once
// Which tet contains a point: a uniform grid of buckets over the mesh's bounding box, each
// holding the tets whose bounding boxes overlap it.
#include <Eigen/Core>
#include <vector>

#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

class TetLocator {
 public:
  // Keeps a reference: `mesh` must outlive the locator and stay unchanged.
  explicit TetLocator(const TetMesh& mesh);
  // A tet containing p (barycentric coordinates all >= -tolerance), or -1.
  int find(const Eigen::Vector3d& p, double tolerance = 1e-9) const;

 private:
  int64_t bucket_of(const Eigen::Vector3i& cell) const;
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const;

  const TetMesh* mesh_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double cell_mm_ = 1;
  Eigen::Vector3i cells_ = Eigen::Vector3i::Ones();
  std::vector<int> offsets_;  // buckets in compressed rows
  std::vector<int> tets_;
};

}  // namespace maxillo::softtissue
