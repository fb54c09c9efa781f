#pragma once
// The fast path for plan changes. In a surgical plan every join point follows its bone
// segment rigidly: u(X) = (R_s - I) X + t_s for the segment s it touches, 12 numbers per
// segment (the entries of A_s = R_s - I and t_s). The linear answer is linear in those
// numbers, so the responses to each of the 12 unit parameters of each moved segment are
// solved once (12 re-solves with the cached factorisation per segment); any later plan is
// then their weighted sum: about a millisecond for 20,000 nodes, exact up to round-off.
// Segment -1 marks constrained nodes that never move (fixed); free nodes carry no segment.
#include <Eigen/Geometry>

#include <vector>

#include "softtissue/factorised_elasticity.h"

namespace maxillo::softtissue {

struct RigidPlanBasis {
  int segment_count = 0;
  // responses[12 s + c] (n x 3, mm): the answer when parameter c of segment s is 1 and all
  // others 0; c = 3 r + k is A(r, k) for c < 9, and t(c - 9) after.
  std::vector<Eigen::MatrixX3d> responses;
};

// segment_of_node: n entries, the segment (0 .. segment_count-1) of each prescribed node;
// ignored for free and fixed nodes.
RigidPlanBasis precompute_rigid_plan_basis(const FactorisedElasticity& factorised, const TetMesh& mesh,
                                           const std::vector<NodeConstraint>& constraint,
                                           const std::vector<int>& segment_of_node, int segment_count);

// Displacement of every node (n x 3, mm) when segment s moves by motion[s] (mesh frame, mm).
Eigen::MatrixX3d solve_rigid_plan(const RigidPlanBasis& basis, const std::vector<Eigen::Isometry3d>& motion);

}  // namespace maxillo::softtissue
