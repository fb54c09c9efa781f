// Repairs of meshes with known defects: pinched vertices, fins, small holes.
#include "mesh/mesh_repair.h"

#include <gtest/gtest.h>

#include "geometry/mesh_measures.h"
#include "support/test_shapes.h"

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

TEST(MeshRepair, SplittingPinchedVerticesMakesTheSurfaceManifold) {
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

TEST(MeshRepair, RemovesDoubleSidedFins) {
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

TEST(MeshRepair, ClosesOnlySmallHoles) {
  TriangleMesh m = testing::cube(1);
  m.faces.conservativeResize(10, 3);  // both triangles of the x = 1 side gone: a 4-edge hole
  EXPECT_EQ(close_small_holes(m, 3), 0);
  EXPECT_EQ(close_small_holes(m, 4), 1);
  EXPECT_TRUE(is_watertight(m));
  EXPECT_NEAR(signed_volume(m), 1, 1e-12);
}

}  // namespace
}  // namespace maxillo
