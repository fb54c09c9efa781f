#include "softtissue/calculix_deck.h"

#include <limits>
#include <sstream>

#include "core/error.h"

namespace maxillo::softtissue {
namespace {

void write_nodes_and_elements(std::ostream& deck, const TetMesh& mesh) {
  deck << "*NODE, NSET=NALL\n";
  for (int i = 0; i < mesh.node_count(); ++i)
    deck << i + 1 << ", " << mesh.nodes(i, 0) << ", " << mesh.nodes(i, 1) << ", " << mesh.nodes(i, 2) << "\n";
  deck << "*ELEMENT, TYPE=C3D4, ELSET=EALL\n";
  for (int t = 0; t < mesh.tet_count(); ++t)
    deck << t + 1 << ", " << mesh.tets(t, 0) + 1 << ", " << mesh.tets(t, 1) + 1 << ", " << mesh.tets(t, 2) + 1 << ", "
         << mesh.tets(t, 3) + 1 << "\n";
}

void write_held_nodes(std::ostream& deck, const BoundaryConditions& bc) {
  deck << "*NSET, NSET=HELD\n";
  bool any = false;
  for (int i = 0; i < bc.node_count(); ++i)
    if (bc.constraint[size_t(i)] == NodeConstraint::kFixed) deck << i + 1 << ",\n", any = true;
  if (!any) throw Error(ErrorCode::kBadValue, "CalculiX deck", "no fixed node: the solve has no answer");
}

// Each prescribed node's three displacements, in the step.
void write_prescribed_moves(std::ostream& deck, const BoundaryConditions& bc) {
  deck << "*BOUNDARY\n";
  for (int i = 0; i < bc.node_count(); ++i) {
    if (bc.constraint[size_t(i)] != NodeConstraint::kPrescribed) continue;
    for (int k = 0; k < 3; ++k)
      deck << i + 1 << ", " << k + 1 << ", " << k + 1 << ", " << bc.displacement(i, k) << "\n";
  }
}

}  // namespace

std::string calculix_deck(const TetMesh& mesh, const Material& material, const BoundaryConditions& bc,
                          CalculixStep step) {
  if (any_sliding(bc))
    throw Error(ErrorCode::kBadValue, "CalculiX deck", "sliding nodes are not written (an equation per node)");
  std::ostringstream deck;
  deck.precision(17);
  write_nodes_and_elements(deck, mesh);
  write_held_nodes(deck, bc);
  deck << "*MATERIAL, NAME=TISSUE\n*ELASTIC\n" << material.young_modulus_mpa << ", " << material.poisson_ratio << "\n";
  deck << "*SOLID SECTION, ELSET=EALL, MATERIAL=TISSUE\n";
  deck << "*BOUNDARY\nHELD, 1, 3, 0.\n";
  if (step == CalculixStep::kLinear) {
    deck << "*STEP\n*STATIC\n";
  } else {
    deck << "*STEP, NLGEOM, INC=100\n*STATIC\n0.1, 1.0\n";
    deck << "*CONTROLS, PARAMETERS=FIELD\n1e-9, 1e-9, , , 1e-9\n";
  }
  write_prescribed_moves(deck, bc);
  deck << "*NODE PRINT, NSET=NALL\nU\n*END STEP\n";
  return deck.str();
}

Eigen::MatrixX3d read_calculix_displacements(std::istream& dat, int node_count) {
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Constant(node_count, 3, std::numeric_limits<double>::quiet_NaN());
  std::string line;
  while (std::getline(dat, line)) {
    std::istringstream row(line);
    int node = 0;
    double x = 0, y = 0, z = 0;
    if (row >> node >> x >> y >> z && node >= 1 && node <= node_count) u.row(node - 1) << x, y, z;
  }
  return u;
}

}  // namespace maxillo::softtissue
