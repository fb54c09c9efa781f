#pragma once
// A structured tetrahedralisation of the cube [0, side]^3 (mm): k^3 hexahedra, each split
// into 5 tets (alternating by parity so neighbouring faces match) or 6 tets (Kuhn split along
// the main diagonal). Node (i, j, l) of the (k+1)^3 grid has index i + (k+1) * (j + (k+1) * l)
// and lies at side / k * (i, j, l). Used by the cube benchmark (thesis ch. 6, fig. 2).
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

enum class HexSplit { kFiveTets, kSixTets };

struct CubeSpec {
  double side_mm = 100.0;
  int divisions = 10;  // k hexahedra along each edge
  HexSplit split = HexSplit::kSixTets;
};

TetMesh make_cube_mesh(const CubeSpec& spec);

int tets_per_hex(HexSplit split);
// The k whose cube has the tet count closest to target_tets (at least 1).
int cube_divisions_for_tets(int target_tets, HexSplit split);

}  // namespace maxillo::softtissue
