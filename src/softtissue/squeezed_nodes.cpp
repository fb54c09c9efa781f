#include "softtissue/squeezed_nodes.h"

namespace maxillo::softtissue {
namespace {

// Tet t's volume with its corners moved by what their constraints impose.
double held_volume(const TetMesh& mesh, const BoundaryConditions& bc, int t) {
  Eigen::Matrix<double, 4, 3> c = tet_corners(mesh, t);
  for (int k = 0; k < 4; ++k) c.row(k) += bc.imposed(mesh.tets(t, k)).transpose();
  return (c.row(1) - c.row(0)).cross(c.row(2) - c.row(0)).dot(c.row(3) - c.row(0)) / 6;
}

bool has_corner(const TetMesh& mesh, const BoundaryConditions& bc, int t, NodeConstraint constraint) {
  for (int k = 0; k < 4; ++k)
    if (bc.constraint[size_t(mesh.tets(t, k))] == constraint) return true;
  return false;
}

}  // namespace

int release_squeezed_sliding_nodes(const TetMesh& mesh, BoundaryConditions& bc, double smallest_volume_fraction) {
  std::vector<int> squeezed;
  for (int t = 0; t < mesh.tet_count(); ++t) {
    // Between a sliding node and a held one, with nothing free to give way.
    if (has_corner(mesh, bc, t, NodeConstraint::kFree) || !has_corner(mesh, bc, t, NodeConstraint::kFixed) ||
        !has_corner(mesh, bc, t, NodeConstraint::kSliding))
      continue;
    if (held_volume(mesh, bc, t) >= smallest_volume_fraction * signed_volume(mesh, t)) continue;
    for (int k = 0; k < 4; ++k)
      if (bc.constraint[size_t(mesh.tets(t, k))] == NodeConstraint::kSliding) squeezed.push_back(mesh.tets(t, k));
  }
  int released = 0;
  for (int i : squeezed) {  // judged on the constraints as they were, then freed
    if (bc.constraint[size_t(i)] != NodeConstraint::kSliding) continue;
    bc.constraint[size_t(i)] = NodeConstraint::kFree;
    bc.displacement.row(i).setZero();
    ++released;
  }
  return released;
}

}  // namespace maxillo::softtissue
