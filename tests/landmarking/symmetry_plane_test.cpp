// The midsagittal plane of a synthetic mirror-symmetric head placed at a known tilt and offset:
// the symmetry search must give that plane back, and the refinement on the grey values must
// bring it to a fraction of the voxel.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "imaging/grey_calibration.h"
#include "landmarking/bone_surface.h"
#include "landmarking/symmetry_plane.h"

namespace maxillo::landmarking {
namespace {

// A skull-like object in its own frame, symmetric in x: an ellipsoidal shell (the vault), a
// "face" block in front, a "jaw" bar below and two lateral bumps; asymmetric front to back and
// top to bottom, as a head is.
bool bone_at(const Eigen::Vector3d& q) {
  const double shell = std::pow(q.x() / 60, 2) + std::pow((q.y() - 10) / 80, 2) + std::pow((q.z() - 20) / 70, 2);
  if (shell < 1 && shell > 0.8) return true;
  if (std::abs(q.x()) < 30 && q.y() > -80 && q.y() < -60 && q.z() > -40 && q.z() < 0) return true;    // face
  if (std::abs(q.x()) < 40 && q.y() > -70 && q.y() < -20 && q.z() > -60 && q.z() < -52) return true;  // jaw
  const Eigen::Vector3d bump(std::abs(q.x()) - 45, q.y() + 20, q.z() + 10);
  return bump.norm() < 8;
}

struct PlacedHead {
  Volume ct;
  Plane truth;
};

// The object turned and shifted into the scan; its symmetry plane follows.
PlacedHead placed_head(const Eigen::Matrix3d& turn, const Eigen::Vector3d& shift, double spacing) {
  PlacedHead head;
  auto& g = head.ct.geometry;
  g.spacing.setConstant(spacing);
  g.size.setConstant(int(200 / spacing));
  g.origin.setConstant(-100);
  head.ct.hu.resize(size_t(g.voxel_count()));
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d q = turn.transpose() * (g.world(Eigen::Vector3d(i, j, k)) - shift);
        head.ct.at(i, j, k) = bone_at(q) ? 1200 : (q.norm() < 95 ? 40 : -1000);
      }
  head.truth.normal = turn.col(0);
  head.truth.offset = head.truth.normal.dot(shift);
  return head;
}

TEST(SymmetryPlane, AHeadTurnedAndShiftedGivesItsPlaneBack) {
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(9 * kDeg, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-6 * kDeg, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  const PlacedHead head = placed_head(turn, {3.2, -5, 2}, 1.25);
  const GreyCalibration grey;  // HU as stored
  const BoneSurface bone = sample_bone_surface(head.ct, 400, 1.5);
  ASSERT_GT(bone.points.size(), 1000u);
  const SymmetryPlane coarse = find_symmetry_plane(bone.points, *bone.distance, {{1, 0, 0}, bone.bone_centre.x()});
  const double coarse_angle = std::acos(std::min(1.0, std::abs(coarse.plane.normal.dot(head.truth.normal)))) / kDeg;
  EXPECT_LT(coarse_angle, 1.0);
  const Plane fine = refine_on_grey_values(head.ct, grey, bone.points, coarse.plane);
  const double angle = std::acos(std::min(1.0, std::abs(fine.normal.dot(head.truth.normal)))) / kDeg;
  const double sign = fine.normal.dot(head.truth.normal) > 0 ? 1 : -1;
  EXPECT_LT(angle, 0.2) << "coarse " << coarse_angle << " deg";
  EXPECT_NEAR(sign * fine.offset, head.truth.offset, 0.2);
  EXPECT_LT(coarse.mean_distance_mm, 1.0);  // a symmetric object mirrors onto itself
}

TEST(SymmetryPlane, TheSameAnswerToTheBitEveryTime) {
  const PlacedHead head = placed_head(Eigen::Matrix3d::Identity(), {1, 2, 3}, 2.0);
  const BoneSurface bone = sample_bone_surface(head.ct, 400, 1.5);
  const Plane start{{1, 0, 0}, bone.bone_centre.x()};
  const SymmetryPlane a = find_symmetry_plane(bone.points, *bone.distance, start);
  const SymmetryPlane b = find_symmetry_plane(bone.points, *bone.distance, start);
  EXPECT_EQ(a.plane.normal, b.plane.normal);
  EXPECT_EQ(a.plane.offset, b.plane.offset);
  EXPECT_NEAR(a.plane.offset, 1, 0.75);
}

}  // namespace
}  // namespace maxillo::landmarking
