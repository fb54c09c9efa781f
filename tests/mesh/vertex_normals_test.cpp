// Vertex normals on shapes whose normals are known: a sphere's point outwards along the radius, a cube's corners
// along the diagonal.
#include "mesh/vertex_normals.h"

#include <gtest/gtest.h>

#include "mesh/surface_extraction.h"
#include "test_shapes.h"

namespace maxillo {
namespace {

TEST(VertexNormals, SphereNormalsPointAlongTheRadius) {
  const Eigen::Vector3d centre(20, 20, 20);
  const TriangleMesh sphere = extract_surface(testing::sphere_volume(41, centre, 12), 0, {.smoothing_iterations = 0});
  const VertexMatrix normals = vertex_normals(sphere);
  // Marching cubes leaves a few vertices whose triangles all have zero area: those get no normal.
  int without_normal = 0;
  double worst_cosine = 1;
  for (Eigen::Index v = 0; v < sphere.vertex_count(); ++v) {
    if (normals.row(v).norm() == 0) {
      ++without_normal;
      continue;
    }
    const Eigen::Vector3d radial = (sphere.vertices.row(v).transpose() - centre).normalized();
    EXPECT_NEAR(normals.row(v).norm(), 1.0, 1e-12);
    worst_cosine = std::min(worst_cosine, radial.dot(normals.row(v).transpose()));
  }
  EXPECT_LT(without_normal, sphere.vertex_count() / 200);
  EXPECT_GT(worst_cosine,
            0.98);  // within ~11 degrees of the radius on a 12-voxel sphere
}

TEST(VertexNormals, CubeCornersPointOutwardsAlongTheirDiagonal) {
  const TriangleMesh cube = testing::cube(2);
  const VertexMatrix normals = vertex_normals(cube);
  for (Eigen::Index v = 0; v < 8; ++v) {
    const Eigen::Vector3d outward = (cube.vertices.row(v).transpose() - Eigen::Vector3d(1, 1, 1)).normalized();
    // Area weighting counts each corner's two triangles on some faces and one on others, so the normal leans towards
    // the faces with two: it stays in the corner's outward octant.
    EXPECT_GT(outward.dot(normals.row(v).transpose()), 0.9);
    for (int axis = 0; axis < 3; ++axis) EXPECT_GT(outward[axis] * normals(v, axis), 0);
  }
}

TEST(VertexNormals, IsolatedVertexGetsZero) {
  TriangleMesh mesh = testing::cube(1);
  mesh.vertices.conservativeResize(9, 3);
  mesh.vertices.row(8) << 5, 5, 5;
  EXPECT_EQ(vertex_normals(mesh).row(8).norm(), 0.0);
}

}  // namespace
}  // namespace maxillo
