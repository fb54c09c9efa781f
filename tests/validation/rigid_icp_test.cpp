// Rigid ICP recovers known rigid moves: from the identity, from a start 3 mm / 3 degrees off,
// and onto a target that lacks part of the moving surface (a segment's cut faces).
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

#include "core/error.h"
#include "geometry/mesh_transform.h"
#include "test_surfaces.h"
#include "validation/rigid_icp.h"

namespace maxillo::validation {
namespace {

Eigen::Isometry3d rigid(double degrees, const Eigen::Vector3d& axis, const Eigen::Vector3d& translation) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
  t.translation() = translation;
  return t;
}

// The largest distance between where `found` and `truth` put a vertex of `mesh`.
double largest_vertex_error(const TriangleMesh& mesh, const Eigen::Isometry3d& found, const Eigen::Isometry3d& truth) {
  double worst = 0;
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector3d p = mesh.vertices.row(v).transpose();
    worst = std::max(worst, (found * p - truth * p).norm());
  }
  return worst;
}

// The faces of `mesh` whose centroid satisfies `keep` (vertices kept as they are).
template <typename Keep>
TriangleMesh faces_where(const TriangleMesh& mesh, Keep keep) {
  TriangleMesh part;
  part.vertices = mesh.vertices;
  part.faces.resize(mesh.face_count(), 3);
  Eigen::Index n = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) c += mesh.vertices.row(mesh.faces(f, k)).transpose() / 3.0;
    if (keep(c)) part.faces.row(n++) = mesh.faces.row(f);
  }
  part.faces.conservativeResize(n, 3);
  return part;
}

class RigidIcp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { shape_ = new TriangleMesh(test::knobbly_ellipsoid()); }
  static void TearDownTestSuite() { delete shape_; }
  static const TriangleMesh& shape() { return *shape_; }
  static inline TriangleMesh* shape_ = nullptr;
};

TEST_F(RigidIcp, RecoversAKnownMoveFromTheIdentity) {
  const Eigen::Isometry3d truth = rigid(4, {1, 2, 3}, {2.0, -1.5, 1.0});
  const TriangleMesh target = transformed(shape(), truth);
  IcpOptions options;
  options.max_pair_distance_mm = 8;
  const IcpResult result = rigid_icp(shape(), target, Eigen::Isometry3d::Identity(), options);
  EXPECT_LT(largest_vertex_error(shape(), result.transform, truth), 1e-3);
  EXPECT_LT(result.rms_mm, 1e-3);
  const Eigen::Index samples = std::min<Eigen::Index>(shape().vertex_count(), options.max_samples);
  EXPECT_GT(result.pairs, samples * 9 / 10);
  EXPECT_LT(result.iterations, options.max_iterations);
}

TEST_F(RigidIcp, ConvergesFromAStartThreeMillimetresAndThreeDegreesOff) {
  const Eigen::Isometry3d truth = rigid(12, {0, 0, 1}, {5, 8, -3});  // e.g. the actual move of a segment
  const TriangleMesh target = transformed(shape(), truth);
  const Eigen::Isometry3d start = rigid(3, {1, -1, 0.5}, Eigen::Vector3d(2, -2, 1).normalized() * 3.0) * truth;
  ASSERT_GT(largest_vertex_error(shape(), start, truth), 3.0);
  const IcpResult result = rigid_icp(shape(), target, start);
  EXPECT_LT(largest_vertex_error(shape(), result.transform, truth), 1e-3);
}

TEST_F(RigidIcp, ExtraMovingFacesWithoutCounterpartDoNotBiasTheResult) {
  const Eigen::Isometry3d truth = rigid(6, {1, 0, 1}, {-4, 3, 2});
  // The target lacks the ellipsoid's end below x = -18 (as the post-operative bone lacks a segment's cut faces).
  const TriangleMesh partial = faces_where(shape(), [](const Eigen::Vector3d& c) { return c.x() > -18; });
  ASSERT_LT(partial.face_count(), shape().face_count() * 95 / 100);
  const TriangleMesh target = transformed(partial, truth);
  const Eigen::Isometry3d start = rigid(2, {0, 1, 0}, {1.5, 0, -1}) * truth;
  const IcpResult result = rigid_icp(shape(), target, start);
  EXPECT_LT(largest_vertex_error(shape(), result.transform, truth), 1e-3);
  EXPECT_LT(result.rms_mm, 1e-3);
}

TEST_F(RigidIcp, AnEmptyMeshOrATargetOutOfReachIsRefused) {
  EXPECT_THROW(rigid_icp(TriangleMesh{}, shape(), Eigen::Isometry3d::Identity()), Error);
  EXPECT_THROW(rigid_icp(shape(), TriangleMesh{}, Eigen::Isometry3d::Identity()), Error);
  const TriangleMesh far_away = transformed(shape(), rigid(0, {0, 0, 1}, {500, 0, 0}));
  EXPECT_THROW(rigid_icp(shape(), far_away, Eigen::Isometry3d::Identity()), Error);
}

}  // namespace
}  // namespace maxillo::validation
