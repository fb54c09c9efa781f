#pragma once
// Boundary conditions of a static soft tissue solve, apart from the mesh and from any solver
// state. Each node is
//   free        its displacement is solved for;
//   fixed       displacement zero: it touches unmoved bone or lies on a cut boundary of the region;
//   prescribed  a join point that follows its bone segment (thesis ch. 6): displacement given;
//   sliding     it lies on a moved bone's surface and slides on it (issue 34): its move along the
//               bone's normal is the bone's, the two directions across the normal are solved for.
//               In a Le Fort I the tissue over the maxilla is lifted off the bone (subperiosteal
//               dissection) and the lips lie on the teeth: the bone pushes the tissue where it moves
//               against it and leaves it where it moves along under it.
// Displacements are in mm, in the mesh frame.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace maxillo::softtissue {

// The integer values are those written to the VTU "bc" array.
enum class NodeConstraint : std::uint8_t { kFree = 0, kFixed = 1, kPrescribed = 2, kSliding = 3 };

struct BoundaryConditions {
  std::vector<NodeConstraint> constraint;  // n
  // n x 3, mm: the bone's move at the node, read for prescribed nodes (all of it) and sliding
  // nodes (its component along the node's normal).
  Eigen::MatrixX3d displacement;
  Eigen::MatrixX3d normal;  // n x 3, unit; read only for sliding nodes (the bone surface's normal)

  int node_count() const { return int(constraint.size()); }
  bool is_free(int i) const { return constraint[size_t(i)] == NodeConstraint::kFree; }
  // Whether any direction of node i is solved for (free or sliding).
  bool has_free_directions(int i) const {
    return constraint[size_t(i)] == NodeConstraint::kFree || constraint[size_t(i)] == NodeConstraint::kSliding;
  }
  // The displacement the constraint imposes on node i: all of it for prescribed nodes, zero for
  // fixed and free ones, the component along the normal for sliding ones.
  Eigen::Vector3d imposed(int i) const;
  // The part of v in the directions node i may move in: all of v (free), its component across the
  // normal (sliding), none (fixed, prescribed).
  Eigen::Vector3d free_part(int i, const Eigen::Vector3d& v) const;
  // The inverse of the 3 x 3 block k restricted to node i's free directions: k^-1 for a free node;
  // for a sliding node T (T^T k T)^-1 T^T with T two unit vectors across its normal, so that
  // u = M f solves node i's equations across the normal and moves it only across it; zero else.
  Eigen::Matrix3d restricted_inverse(int i, const Eigen::Matrix3d& k) const;
  // The solution of k u = f restricted to node i's free directions, as restricted_inverse, for a
  // k that may be indefinite (a spring's hessian under compression): by LDL^T.
  Eigen::Vector3d restricted_solve(int i, const Eigen::Matrix3d& k, const Eigen::Vector3d& f) const;
};

// All nodes free, displacements zero.
BoundaryConditions all_free(int node_count);
// Node i slides on a bone surface with unit normal `normal` whose move at the node is `move`.
void make_sliding(BoundaryConditions& bc, int i, const Eigen::Vector3d& normal, const Eigen::Vector3d& move);
int count_nodes(const BoundaryConditions& bc, NodeConstraint constraint);
bool any_sliding(const BoundaryConditions& bc);
// The starting displacement of an iterative solve: imposed values on constrained and sliding
// nodes, zero on free nodes.
Eigen::MatrixX3d initial_displacement(const BoundaryConditions& bc);

}  // namespace maxillo::softtissue
