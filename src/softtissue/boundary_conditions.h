#pragma once
// Boundary conditions of a static soft tissue solve, apart from the mesh and from any solver
// state. Each node is free (its displacement is solved for), fixed (displacement zero: touches
// unmoved bone or lies on a cut boundary of the region) or prescribed (a join point that
// follows its bone segment; displacement given). Displacements are in mm, in the mesh frame.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace maxillo::softtissue {

// The integer values are those written to the VTU "bc" array.
enum class NodeConstraint : std::uint8_t { kFree = 0, kFixed = 1, kPrescribed = 2 };

struct BoundaryConditions {
  std::vector<NodeConstraint> constraint;  // n
  Eigen::MatrixX3d displacement;           // n x 3, mm; read only for prescribed nodes

  int node_count() const { return int(constraint.size()); }
  bool is_free(int i) const { return constraint[size_t(i)] == NodeConstraint::kFree; }
  // The displacement a constrained node must have (zero for fixed nodes).
  Eigen::Vector3d imposed(int i) const;
};

// All nodes free, displacements zero.
BoundaryConditions all_free(int node_count);
int count_nodes(const BoundaryConditions& bc, NodeConstraint constraint);
// The starting displacement of an iterative solve: imposed values on constrained nodes, zero
// on free nodes.
Eigen::MatrixX3d initial_displacement(const BoundaryConditions& bc);

}  // namespace maxillo::softtissue
