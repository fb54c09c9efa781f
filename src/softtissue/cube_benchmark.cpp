#include "softtissue/cube_benchmark.h"

namespace maxillo::softtissue {

BoundaryConditions cube_benchmark_conditions(const TetMesh& mesh, const CubeSpec& spec, const CubeLoad& load) {
  BoundaryConditions bc = all_free(mesh.node_count());
  const double tolerance = 1e-9 * spec.side_mm, centre = spec.side_mm / 2;
  for (int i = 0; i < mesh.node_count(); ++i) {
    Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    bool on_border = (p.array() <= tolerance).any() || (p.array() >= spec.side_mm - tolerance).any();
    bool in_centre = ((p.array() - centre).abs() <= load.centre_half_width_mm + tolerance).all();
    if (on_border) {
      bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    } else if (in_centre) {
      bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      bc.displacement.row(i) << 0.0, 0.0, load.lift_mm;
    }
  }
  return bc;
}

}  // namespace maxillo::softtissue
