#include "softtissue/face_region.h"

#include <algorithm>
#include <cmath>

namespace maxillo::softtissue {
namespace {

bool kept_by_all(const std::vector<RegionPlane>& piece, const Eigen::Vector3d& p) {
  return std::all_of(piece.begin(), piece.end(), [&](const RegionPlane& c) { return c.side(p) > 0; });
}

}  // namespace

bool RegionShape::contains(const Eigen::Vector3d& p) const {
  return std::any_of(pieces.begin(), pieces.end(), [&](const auto& piece) { return kept_by_all(piece, p); });
}

bool RegionShape::cut_behind(const Eigen::Vector3d& p, size_t piece, size_t plane, double tolerance) const {
  const RegionPlane& face = pieces[piece][plane];
  const Eigen::Vector3d stepped_out = p - (face.side(p) + tolerance) * face.normal;
  return !contains(stepped_out);
}

bool RegionShape::on_cut(const Eigen::Vector3d& p, double tolerance) const {
  for (size_t k = 0; k < pieces.size(); ++k)
    for (size_t q = 0; q < pieces[k].size(); ++q)
      if (std::abs(pieces[k][q].side(p)) <= tolerance && cut_behind(p, k, q, tolerance)) return true;
  return false;
}

std::vector<RegionPlane> RegionShape::planes() const {
  std::vector<RegionPlane> all;
  for (const auto& piece : pieces) all.insert(all.end(), piece.begin(), piece.end());
  return all;
}

LabelVolume face_region(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels, const RegionShape& shape) {
  const auto& g = tissues.geometry;
  LabelVolume region;
  region.geometry = g;
  region.labels.assign(tissues.labels.size(), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const auto v = size_t(g.index(i, j, k));
        if (std::find(soft_labels.begin(), soft_labels.end(), tissues.labels[v]) == soft_labels.end()) continue;
        region.labels[v] = shape.contains(g.world(Eigen::Vector3d(i, j, k))) ? 1 : 0;
      }
  return region;
}

}  // namespace maxillo::softtissue
