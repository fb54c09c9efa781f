// The simulated intraoral scan on a known shape: a box-shaped "tooth" 20 mm long keeps the crown
// end only, gains a collar and is split into four times the triangles.
#include <gtest/gtest.h>

#include "sample/simulated_dental_scan.h"
#include "support/test_shapes.h"

namespace maxillo {
namespace {

TEST(SplitTriangles, FourTimesTheTrianglesOnTheSameSurface) {
  TriangleMesh triangle;
  triangle.vertices.resize(3, 3);
  triangle.vertices << 0, 0, 0, 2, 0, 0, 0, 2, 0;
  triangle.faces.resize(1, 3);
  triangle.faces << 0, 1, 2;
  const TriangleMesh split = split_triangles(triangle);
  EXPECT_EQ(split.face_count(), 4);
  EXPECT_EQ(split.vertex_count(), 6);
  double area = 0;
  for (Eigen::Index f = 0; f < split.face_count(); ++f) {
    const Eigen::Vector3d a = split.vertices.row(split.faces(f, 0)).transpose(),
                          b = split.vertices.row(split.faces(f, 1)).transpose(),
                          c = split.vertices.row(split.faces(f, 2)).transpose();
    const Eigen::Vector3d n = (b - a).cross(c - a);
    EXPECT_GT(n.z(), 0);  // the same orientation
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 2.0, 1e-12);
}

// A box-shaped tooth 4 x 4 x 20 mm biting upwards: its crown (the top 8 mm) is the top face only
// (the side faces reach the root), the collar a ring of 8 triangles 2 mm out and 1 mm down from
// the top face's edges, oriented as the crown, and every triangle is split in four.
TEST(SimulatedDentalScan, KeepsTheCrownAndAddsACollarOnABoxTooth) {
  TriangleMesh tooth = testing::cube(1);
  tooth.vertices = tooth.vertices * Eigen::Vector3d(4, 4, 20).asDiagonal();
  DentalScanOptions options;
  options.noise_mm = 0;
  const TriangleMesh scan = simulated_dental_scan({tooth}, Eigen::Vector3d(2, 2, 100), options);
  EXPECT_EQ(scan.face_count(), 4 * (2 + 8));
  int collar = 0;
  for (Eigen::Index v = 0; v < scan.vertex_count(); ++v) {
    const Eigen::Vector3d p = scan.vertices.row(v).transpose();
    EXPECT_GE(p.z(), 19 - 1e-9);  // nothing of the root
    if (p.z() < 20 - 1e-9) ++collar;
  }
  EXPECT_GT(collar, 0);
  for (Eigen::Index f = 0; f < scan.face_count(); ++f) {  // every triangle faces up, as the crown's top
    const Eigen::Vector3d a = scan.vertices.row(scan.faces(f, 0)).transpose(),
                          b = scan.vertices.row(scan.faces(f, 1)).transpose(),
                          c = scan.vertices.row(scan.faces(f, 2)).transpose();
    EXPECT_GT((b - a).cross(c - a).z(), 0) << "face " << f;
  }
}

}  // namespace
}  // namespace maxillo
