#include "occlusion/arch_repair.h"

#include <gtest/gtest.h>

#include "support/test_meshes.h"

namespace maxillo::occlusion {
namespace {

TEST(RepairArch, ReversesInwardShellsOnlyAndDropsDegenerateFaces) {
  TriangleMesh inward = testing::make_box({3, 0, 0}, {4, 1, 1});
  inward.faces.col(1).swap(inward.faces.col(2));
  TriangleMesh mesh = testing::append(testing::make_box({0, 0, 0}, {1, 1, 1}), inward);
  mesh.faces.conservativeResize(mesh.face_count() + 1, 3);
  mesh.faces.row(mesh.face_count() - 1) << 0, 0, 1;  // zero area
  const FaceMatrix outward_faces =
      testing::append(testing::make_box({0, 0, 0}, {1, 1, 1}), testing::make_box({3, 0, 0}, {4, 1, 1})).faces;
  const ArchRepairReport report = repair_arch(mesh);
  EXPECT_EQ(report.shells, 2);
  EXPECT_EQ(report.shells_flipped, 1);
  EXPECT_EQ(report.degenerate_faces_removed, 1);
  EXPECT_EQ(report.open_edges, 0);
  EXPECT_EQ(report.notes.size(), 2u);
  EXPECT_TRUE(mesh.faces == outward_faces);
  // A second pass finds nothing to repair.
  EXPECT_EQ(repair_arch(mesh).shells_flipped, 0);
}

TEST(RepairArch, ReportsOpenShells) {
  TriangleMesh mesh = testing::make_box({0, 0, 0}, {1, 1, 1});
  mesh.faces.conservativeResize(10, 3);  // drop the x = hi side
  EXPECT_EQ(repair_arch(mesh).open_edges, 4);
}

}  // namespace
}  // namespace maxillo::occlusion
