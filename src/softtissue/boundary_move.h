#pragma once
// How far a solved face model still moves next to its cut planes. The nodes on a plane are held
// fixed (bone_attachment.h), which is right only where the move has died out before the plane:
// a large move just inside it means the plane cuts through tissue that the bone move carries (a
// shear at the model's edge, issue 34). The region is large enough for a move when this is below
// 0.1 mm at every plane.
#include <Eigen/Core>
#include <vector>

#include "softtissue/face_region.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

inline constexpr double kBoundaryBandMm = 5;   // how far inside a plane its nodes are looked at
inline constexpr double kDecayedMoveMm = 0.1;  // a move this small at every plane: the region suffices

// Per plane of the shape (RegionShape::planes() order), the largest displacement (mm) of the
// nodes on its kept side within `band_mm` of it where it cuts tissue (a step out through it
// leaves the shape: not where two pieces meet); 0 for a plane with no such node.
std::vector<double> largest_move_near_planes(const TetMesh& mesh, const Eigen::MatrixX3d& displacement,
                                             const RegionShape& shape, double band_mm = kBoundaryBandMm);

}  // namespace maxillo::softtissue
