// Area, volume, edges and components on meshes with known answers.
#include "geometry/mesh_measures.h"

#include <gtest/gtest.h>

#include "support/test_shapes.h"

namespace maxillo {
namespace {

TEST(MeshMeasures, CubeAreaVolumeAndClosure) {
  TriangleMesh c = testing::cube(2);
  EXPECT_DOUBLE_EQ(surface_area(c), 24);
  EXPECT_NEAR(signed_volume(c), 8, 1e-12);
  EXPECT_TRUE(is_watertight(c));
}

TEST(MeshMeasures, VolumeDoesNotDependOnWhereTheMeshIs) {
  TriangleMesh c = testing::cube(1);
  c.vertices.rowwise() += Eigen::RowVector3d(1e5, -2e5, 3e5);
  EXPECT_NEAR(signed_volume(c), 1, 1e-6);
}

TEST(MeshMeasures, OrientOutwardRepairsAnInsideOutMesh) {
  TriangleMesh c = testing::cube(1);
  c.faces.col(0).swap(c.faces.col(1));
  EXPECT_NEAR(signed_volume(c), -1, 1e-12);
  EXPECT_TRUE(is_watertight(c)) << "consistently inside-out is still closed";
  orient_outward(c);
  EXPECT_NEAR(signed_volume(c), 1, 1e-12);
}

TEST(MeshMeasures, DetectsHolesAndInconsistentFaces) {
  TriangleMesh open = testing::cube(1);
  open.faces.conservativeResize(11, 3);
  EXPECT_EQ(count_edges(open).boundary, 3);
  EXPECT_FALSE(is_watertight(open));
  TriangleMesh flipped = testing::cube(1);
  std::swap(flipped.faces(0, 0), flipped.faces(0, 1));
  EXPECT_EQ(count_edges(flipped).inconsistent, 3);
  EXPECT_FALSE(is_watertight(flipped));
}

TEST(MeshMeasures, ComponentsAreRankedBySizeAndFiltered) {
  TriangleMesh small = testing::cube(1), big = testing::cube(1);
  TriangleMesh two;
  two.vertices.resize(16, 3);
  two.vertices << small.vertices, (big.vertices.array() + 5).matrix();
  two.faces.resize(14, 3);
  two.faces << small.faces.topRows(2), (big.faces.array() + 8).matrix();  // 2 faces vs 12
  Components components = connected_components(two);
  ASSERT_EQ(components.face_counts, (std::vector<int64_t>{12, 2}));
  EXPECT_EQ(components.face_label[0], 1);
  EXPECT_EQ(components.face_label[5], 0);
  TriangleMesh largest = keep_largest_components(two, 1);
  EXPECT_EQ(largest.face_count(), 12);
  EXPECT_EQ(largest.vertex_count(), 8);
  EXPECT_NEAR(signed_volume(largest), 1, 1e-12);
  EXPECT_EQ(keep_largest_components(two, 0).face_count(), 14);
  EXPECT_EQ(keep_largest_components(two, 0, 0.5).face_count(), 12) << "2 < 0.5 x 12 faces: dropped";
}

}  // namespace
}  // namespace maxillo
