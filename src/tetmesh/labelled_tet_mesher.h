#pragma once
// A tetrahedral mesh of the voxels of one label (CGAL Mesh_3 on the labelled image): the
// boundary facets follow the region's surface to within facet_distance_mm, the inside is
// filled with well-shaped tets of about cell_size_mm. CGAL stays behind this header.
#include <cstdint>

#include "core/volume.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::tetmesh {

struct TetMeshingOptions {
  double cell_size_mm = 4.0;       // upper bound on a tet's circumradius (and boundary facets' size)
  double facet_distance_mm = 1.0;  // how far a boundary facet may stray from the region's surface
  double facet_angle_deg = 25;     // lower bound on boundary facets' angles
  double radius_edge_ratio = 3.0;  // upper bound on circumradius / shortest edge
  int max_tets = 100000;           // the cell size grows until the mesh has at most this many
  // Sliver perturbation and exudation aim above this dihedral angle and end on their own (the
  // perturber when a degree step fails, the exuder after its pass): no time limit, so the mesh
  // does not depend on the machine's load.
  double sliver_bound_deg = 12;
  int random_seed = 1;  // CGAL's refinement is randomised; fixed for reproducibility
};

struct TetMeshingResult {
  softtissue::TetMesh mesh;  // LPS mm, positively oriented tets
  double cell_size_mm = 0;   // the cell size of the last meshing
  int attempts = 0;          // meshings run (a coarser one after each one over max_tets)
  int tet_budget = 0;        // the max_tets asked for
  double seconds = 0;
  // The budget could not be met within the attempts: the mesh is kept (a coarser one would
  // lose the region's shape), and the caller must say so with these numbers.
  bool over_budget() const { return mesh.tet_count() > tet_budget; }
};

// Meshes the voxels of `volume` equal to `label`, coarsening until the mesh has at most
// options.max_tets tetrahedra or six meshings have run (then over_budget()). Throws
// Error(kEmptyResult) when there are no such voxels.
TetMeshingResult mesh_label(const LabelVolume& volume, uint8_t label, const TetMeshingOptions& options = {});

}  // namespace maxillo::tetmesh
