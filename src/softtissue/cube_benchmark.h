#pragma once
// The thesis' cube test (ch. 6, fig. 2): the cube's border is fixed and its centre is moved
// upward (+z, mm). The "centre" is every node within centre_half_width_mm of the cube's
// centre in each axis, so the prescribed region keeps its size under refinement.
#include "softtissue/boundary_conditions.h"
#include "softtissue/cube_mesh.h"

namespace maxillo::softtissue {

struct CubeLoad {
  double lift_mm = 6.0;
  double centre_half_width_mm = 10.0;
};

BoundaryConditions cube_benchmark_conditions(const TetMesh& mesh, const CubeSpec& spec, const CubeLoad& load = {});

}  // namespace maxillo::softtissue
