#pragma once
// Shape quality of linear tets. A regular tet has all dihedral angles 70.53 degrees and
// aspect ratio 1; slivers drive the minimum dihedral angle to 0 and the aspect ratio up.
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

// Smallest of the 6 dihedral angles of tet t, degrees.
double min_dihedral_angle_deg(const TetMesh& mesh, int t);
// Longest edge over the diameter of the inscribed sphere, normalised so a regular tet gives 1
// (the regular tet's ratio is sqrt(6)); >= 1 for every tet.
double aspect_ratio(const TetMesh& mesh, int t);

struct MeshQuality {
  double min_dihedral_deg = 0;  // smallest over the mesh
  double max_aspect_ratio = 0;  // largest over the mesh
  double mean_aspect_ratio = 0;
};
MeshQuality mesh_quality(const TetMesh& mesh);

}  // namespace maxillo::softtissue
