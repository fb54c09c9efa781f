#pragma once
// The soft tissue solve as a CalculiX input deck, and CalculiX's answer read back: an independent
// solver to check the FEM against (tests/softtissue/calculix_cross_check_test.cpp, `bench cube
// --calculix`). The same tets (C3D4, CalculiX's linear tetrahedron, corners in the mesh's order,
// numbered from 1), the same isotropic material, the fixed nodes held and the prescribed ones
// moved; a static step, linear or with geometric non-linearity (NLGEOM: CalculiX's *ELASTIC
// material is then St Venant-Kirchhoff, HyperelasticLaw::kStVenantKirchhoff here). Sliding nodes
// are not written (CalculiX would need an equation per node): a deck for a mesh with them is an error.
#include <Eigen/Core>
#include <istream>
#include <string>

#include "softtissue/boundary_conditions.h"
#include "softtissue/linear_elasticity.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

enum class CalculixStep { kLinear, kGeometricallyNonlinear };

// The deck; its *NODE PRINT writes every node's displacement to the job's .dat file. The
// non-linear step runs in ten increments with the force residual checked to 1e-9 of the average
// force (CalculiX's default, 5e-3, stops far from equilibrium).
std::string calculix_deck(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
                          CalculixStep step = CalculixStep::kLinear);

// The displacements of a .dat file's last printout ("node ux uy uz" rows), n x 3; NaN for nodes
// it does not list.
Eigen::MatrixX3d read_calculix_displacements(std::istream& dat, int node_count);

}  // namespace maxillo::softtissue
