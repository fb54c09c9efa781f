#pragma once
// The part of the soft tissue that a bone move deforms, as a voxel mask: the soft tissue voxels
// inside a region shape set up by the caller from landmarks. Tissue outside is not modelled; the
// model's nodes where the shape cuts through tissue are held fixed (bone_attachment.h).
//
// The shape is a union of convex pieces, each the kept side of its cut planes. One piece is not
// enough for a face: a plane below the orbits cuts the nose at its root, so that the nose hangs
// from the moved lip (issue 34), and a plane above the nasion takes in the eyes and the brain
// behind the forehead. casework/softtissue/soft_tissue_prediction.h's region is the face below the orbits
// and, on request, above them a slab in front of the eyes up the forehead: the nose's root, the
// glabella and the eyelids.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/volume.h"

namespace maxillo::softtissue {

// A cut plane of the region: `point` on it, unit `normal` pointing into the kept side.
struct RegionPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double side(const Eigen::Vector3d& p) const { return normal.dot(p - point); }  // > 0: kept
};

struct RegionShape {
  std::vector<std::vector<RegionPlane>> pieces;  // convex pieces: the kept side of all their planes
  std::vector<std::string> plane_names;          // for reports, in planes() order ("at the brows", ...)

  RegionShape() = default;
  RegionShape(std::vector<RegionPlane> planes) : pieces{std::move(planes)} {}  // NOLINT: one piece
  explicit RegionShape(std::vector<std::vector<RegionPlane>> convex_pieces) : pieces(std::move(convex_pieces)) {}

  // Whether p lies strictly on the kept side of every plane of some piece.
  bool contains(const Eigen::Vector3d& p) const;
  // Whether p lies within `tolerance` of a piece's plane where a step out through that plane
  // (to `tolerance` beyond it) leaves the shape: a cut through tissue. Where two pieces meet,
  // the step lands in the other piece: no cut there.
  bool on_cut(const Eigen::Vector3d& p, double tolerance) const;
  // Whether a step from p out through plane `plane` of piece `piece`, to `tolerance` beyond it,
  // leaves the shape.
  bool cut_behind(const Eigen::Vector3d& p, size_t piece, size_t plane, double tolerance) const;
  // Every piece's planes, pieces in order.
  std::vector<RegionPlane> planes() const;
};

// 1 where `tissues` holds one of `soft_labels` and the voxel centre is inside `shape`, 0
// elsewhere. Same geometry as `tissues`.
LabelVolume face_region(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels, const RegionShape& shape);

}  // namespace maxillo::softtissue
