// Parting a tet mesh along a plane (softtissue/mesh_parting.h) on a structured cube whose answers
// are counted by hand: which faces part, which nodes get a copy, and that two parted blocks
// follow only their own boundary in a static solve.
#include "softtissue/mesh_parting.h"

#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "softtissue/boundary_conditions.h"
#include "softtissue/cube_mesh.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/stiffness_blocks.h"

namespace maxillo::softtissue {
namespace {

// The cube [0, 4]^3 in 4 x 4 x 4 hexahedra of 1 mm, six tets each; parted at z = 2 (where `zone`).
TetMesh small_cube() { return make_cube_mesh({.side_mm = 4, .divisions = 4, .split = HexSplit::kSixTets}); }
PartingSide mid_plane(const std::function<bool(const Eigen::Vector3d&)>& zone) {
  return [zone](const Eigen::Vector3d& p) { return zone(p) ? (p.z() > 2 ? 1 : -1) : 0; };
}
bool everywhere(const Eigen::Vector3d&) { return true; }

double centroid_z(const TetMesh& mesh, int t) { return tet_corners(mesh, t).col(2).mean(); }

double total_volume(const TetMesh& mesh) {
  double volume = 0;
  for (int t = 0; t < mesh.tet_count(); ++t) volume += signed_volume(mesh, t);
  return volume;
}

TEST(MeshParting, APlaneThroughTheWholeCubeMakesTwoBlocks) {
  TetMesh mesh = small_cube();
  const int nodes_before = mesh.node_count();
  const auto parting = part_mesh(mesh, mid_plane(everywhere));
  EXPECT_EQ(parting.faces, 4 * 4 * 2);    // each 1 mm square of the plane, two triangles
  EXPECT_EQ(parting.added_nodes, 5 * 5);  // every node of the plane, once
  EXPECT_EQ(mesh.node_count(), nodes_before + 25);
  EXPECT_NEAR(total_volume(mesh), 64, 1e-9);  // no tet turned or moved
  EXPECT_EQ(count_non_positive_tets(mesh), 0);
  std::set<int> upper, lower;
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int c = 0; c < 4; ++c) (centroid_z(mesh, t) > 2 ? upper : lower).insert(mesh.tets(t, c));
  for (int node : upper) EXPECT_FALSE(lower.count(node)) << "node " << node << " joins the blocks";
  for (int copy = nodes_before; copy < mesh.node_count(); ++copy) EXPECT_EQ(mesh.nodes(copy, 2), 2.0);
}

// A parting over 1 < x < 3 only: its nodes at x = 1 and x = 3 lie where it ends inside the
// tissue and stay one node; those at x = 2 (5 of them, y = 0..4) get a copy, the two on the
// cube's faces y = 0 and y = 4 too (there it opens onto the boundary).
TEST(MeshParting, APartingInsideTheTissueEndsAtItsEdge) {
  TetMesh mesh = small_cube();
  const auto parting = part_mesh(mesh, mid_plane([](const Eigen::Vector3d& p) { return p.x() > 1 && p.x() < 3; }));
  EXPECT_EQ(parting.faces, 2 * 4 * 2);
  EXPECT_EQ(parting.added_nodes, 5);
  for (int copy = mesh.node_count() - 5; copy < mesh.node_count(); ++copy) {
    EXPECT_EQ(mesh.nodes(copy, 0), 2.0);
    EXPECT_EQ(mesh.nodes(copy, 2), 2.0);
  }
  // Nothing to part: a zone without tets, or a plane with every tet on one side.
  TetMesh untouched = small_cube();
  EXPECT_EQ(part_mesh(untouched, mid_plane([](const Eigen::Vector3d& p) { return p.x() > 10; })).faces, 0);
  EXPECT_EQ(part_mesh(untouched, [](const Eigen::Vector3d&) { return 1; }).faces, 0);  // all on one side
  EXPECT_EQ(untouched.node_count(), small_cube().node_count());
}

// Held at z = 0 and moved 0.1 mm along x at z = 4: in one piece the cube shears; parted at z = 2,
// the lower block stays where it is and the upper one moves rigidly with its top.
TEST(MeshParting, PartedBlocksFollowOnlyTheirOwnBoundary) {
  TetMesh mesh = small_cube();
  part_mesh(mesh, mid_plane(everywhere));
  BoundaryConditions bc = all_free(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) {
    if (mesh.nodes(i, 2) == 0) bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    if (mesh.nodes(i, 2) == 4) {
      bc.constraint[size_t(i)] = NodeConstraint::kPrescribed;
      bc.displacement.row(i) << 0.1, 0, 0;
    }
  }
  const auto solution = solve_linear_static(assemble_stiffness_blocks(mesh, {}), bc);
  ASSERT_EQ(solution.status, SolveStatus::kConverged);
  std::vector<bool> in_upper(size_t(mesh.node_count()), false);
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int c = 0; c < 4; ++c)
      if (centroid_z(mesh, t) > 2) in_upper[size_t(mesh.tets(t, c))] = true;
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Eigen::Vector3d expected = in_upper[size_t(i)] ? Eigen::Vector3d(0.1, 0, 0) : Eigen::Vector3d::Zero();
    EXPECT_LT((solution.displacement.row(i).transpose() - expected).norm(), 1e-6) << "node " << i;
  }
}

}  // namespace
}  // namespace maxillo::softtissue
