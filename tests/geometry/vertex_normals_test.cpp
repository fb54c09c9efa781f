// Vertex normals on shapes whose normals are known: a sphere's point outwards along the radius, a cube's corners
// along the diagonal.
#include "geometry/vertex_normals.h"

#include <gtest/gtest.h>

#include "support/test_shapes.h"

namespace maxillo {
namespace {

TEST(VertexNormals, SphereNormalsPointAlongTheRadius) {
  const Eigen::Vector3d centre(20, -5, 7);
  const TriangleMesh sphere = testing::uv_sphere(centre, 12);
  const VertexMatrix normals = vertex_normals(sphere);
  double worst_cosine = 1;
  for (Eigen::Index v = 0; v < sphere.vertex_count(); ++v) {
    const Eigen::Vector3d radial = (sphere.vertices.row(v).transpose() - centre).normalized();
    EXPECT_NEAR(normals.row(v).norm(), 1.0, 1e-12);
    worst_cosine = std::min(worst_cosine, radial.dot(normals.row(v).transpose()));
  }
  // Each vertex's fan is symmetric about its meridian; the bands above and below differ in area,
  // which tilts the normal along the meridian: by 1.3 degrees next to the poles on 24 bands.
  EXPECT_GT(worst_cosine, std::cos(2.0 * M_PI / 180));
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
