// Area, volume, edges and components on meshes with known answers.
#include "mesh/mesh_measures.h"
#include "mesh/mesh_repair.h"

#include <gtest/gtest.h>

#include "test_shapes.h"

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

namespace maxillo {
namespace {

// Two unit cubes touching along the edge x = 1, y = 1 (one sheet pinched against the other).
TriangleMesh cubes_sharing_an_edge() {
  TriangleMesh a = testing::cube(1), b = testing::cube(1);
  b.vertices.col(0).array() += 1;
  b.vertices.col(1).array() += 1;
  TriangleMesh m;
  m.vertices.resize(16, 3);
  m.vertices << a.vertices, b.vertices;
  m.faces.resize(24, 3);
  m.faces << a.faces, (b.faces.array() + 8).matrix();
  // b's vertices 0 (1,1,0) and 4 (1,1,1) are a's vertices 3 and 7: merge them.
  for (Eigen::Index f = 12; f < 24; ++f)
    for (int c = 0; c < 3; ++c) {
      if (m.faces(f, c) == 8) m.faces(f, c) = 3;
      if (m.faces(f, c) == 12) m.faces(f, c) = 7;
    }
  return m;
}

TEST(MeshMeasures, SplittingPinchedVerticesMakesTheSurfaceManifold) {
  TriangleMesh m = cubes_sharing_an_edge();
  EXPECT_EQ(count_edges(m).non_manifold, 1);
  EXPECT_EQ(connected_components(m).face_counts.size(), 1u);
  EXPECT_EQ(split_pinched_vertices(m), 2);
  EXPECT_TRUE(is_watertight(m));
  EXPECT_EQ(connected_components(m).face_counts.size(), 2u);
  EXPECT_NEAR(signed_volume(m), 2, 1e-12);
  TriangleMesh plain = testing::cube(1);
  EXPECT_EQ(split_pinched_vertices(plain), 0);
}

TEST(MeshMeasures, RemovesDoubleSidedFins) {
  TriangleMesh m = testing::cube(1);
  m.faces.conservativeResize(13, 3);
  m.faces.row(12) << m.faces(4, 0), m.faces(4, 2), m.faces(4, 1);  // face 4 again, reversed
  EXPECT_EQ(remove_duplicate_faces(m), 2);
  EXPECT_EQ(m.face_count(), 11);
  EXPECT_EQ(count_edges(m).boundary, 3);
  EXPECT_EQ(close_small_holes(m), 1);
  EXPECT_TRUE(is_watertight(m));
  EXPECT_NEAR(signed_volume(m), 1, 1e-12);
}

TEST(MeshMeasures, ClosesOnlySmallHoles) {
  TriangleMesh m = testing::cube(1);
  m.faces.conservativeResize(10, 3);  // both triangles of the x = 1 side gone: a 4-edge hole
  EXPECT_EQ(close_small_holes(m, 3), 0);
  EXPECT_EQ(close_small_holes(m, 4), 1);
  EXPECT_TRUE(is_watertight(m));
  EXPECT_NEAR(signed_volume(m), 1, 1e-12);
}

}  // namespace
}  // namespace maxillo
