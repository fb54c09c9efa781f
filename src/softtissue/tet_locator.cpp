#include "softtissue/tet_locator.h"

#include <cmath>

#include "softtissue/shape_function_mapping.h"

namespace maxillo::softtissue {

TetLocator::TetLocator(const TetMesh& mesh) : mesh_(&mesh) {
  if (mesh.tet_count() == 0) {
    offsets_.assign(2, 0);
    return;
  }
  const Eigen::Vector3d lo = mesh.nodes.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = mesh.nodes.colwise().maxCoeff().transpose();
  // About one tet per bucket on average: cell volume ~ mesh volume / tet count.
  const double extent_volume = std::max((hi - lo).prod(), 1e-9);
  cell_mm_ = std::max(std::cbrt(extent_volume / mesh.tet_count()) * 1.5, 1e-6);
  origin_ = lo;
  cells_ = ((hi - lo) / cell_mm_).array().floor().cast<int>() + 1;
  const auto bucket_count = size_t(cells_.cast<int64_t>().prod());
  std::vector<int> counts(bucket_count + 1, 0);
  auto for_each_bucket = [&](int t, auto&& visit) {
    const auto corners = tet_corners(mesh, t);
    const Eigen::Vector3i a = cell_of(corners.colwise().minCoeff().transpose());
    const Eigen::Vector3i b = cell_of(corners.colwise().maxCoeff().transpose());
    for (int k = a.z(); k <= b.z(); ++k)
      for (int j = a.y(); j <= b.y(); ++j)
        for (int i = a.x(); i <= b.x(); ++i) visit(bucket_of({i, j, k}));
  };
  for (int t = 0; t < mesh.tet_count(); ++t) for_each_bucket(t, [&](int64_t b) { ++counts[size_t(b) + 1]; });
  for (size_t b = 1; b < counts.size(); ++b) counts[b] += counts[b - 1];
  offsets_ = counts;
  tets_.resize(size_t(counts.back()));
  for (int t = 0; t < mesh.tet_count(); ++t)
    for_each_bucket(t, [&](int64_t b) { tets_[size_t(counts[size_t(b)]++)] = t; });
}

Eigen::Vector3i TetLocator::cell_of(const Eigen::Vector3d& p) const {
  Eigen::Vector3i c = ((p - origin_) / cell_mm_).array().floor().cast<int>();
  return c.cwiseMax(Eigen::Vector3i::Zero()).cwiseMin(cells_ - Eigen::Vector3i::Ones());
}

int64_t TetLocator::bucket_of(const Eigen::Vector3i& c) const {
  return c.x() + int64_t(cells_.x()) * (c.y() + int64_t(cells_.y()) * c.z());
}

int TetLocator::find(const Eigen::Vector3d& p, double tolerance) const {
  if (tets_.empty()) return -1;
  const Eigen::Vector3d relative = (p - origin_) / cell_mm_;
  if ((relative.array() < -1e-9).any() || (relative.array() > cells_.cast<double>().array() + 1e-9).any()) return -1;
  const int64_t b = bucket_of(cell_of(p));
  for (int m = offsets_[size_t(b)]; m < offsets_[size_t(b) + 1]; ++m) {
    const int t = tets_[size_t(m)];
    if (shape_functions(*mesh_, t, p).minCoeff() >= -tolerance) return t;
  }
  return -1;
}

}  // namespace maxillo::softtissue
