// Porion (landmarking/lateral_landmarks.h) on a synthetic temporal bone whose answer is known: a
// block of bone with an oblique air canal (radius 3.5 mm, running medially and 0.35 mm anteriorly
// per mm) that opens at the block's lateral face, and a middle ear behind its deep end, apart or
// joined to the canal as the cadaver's were in one pose. Porion is the canal's top where it leaves
// the bone: on the lateral face, at the axis's y 1.5 mm inside, and the radius above the axis
// (the canal runs level, so its vertical sections are ellipses whose top is the radius high).
#include <gtest/gtest.h>

#include <cmath>

#include "landmarking/lateral_landmarks.h"

namespace maxillo::landmarking {
namespace {

constexpr double kLateralFace = 75;  // |x| of the bone's lateral face (mm)
constexpr double kRadius = 3.5;
constexpr double kAnteriorPerMm = 0.35;  // the canal's y falls by this per mm medially
constexpr double kCanalLength = 20;

// The canal's axis at `depth` mm medial to the lateral face (side +1: at x = face - depth).
Eigen::Vector2d axis_yz(double depth) { return {-kAnteriorPerMm * depth, 0}; }

// The grey value at a point of the left side's geometry (x > 0); `joined`: the middle ear meets
// the canal's deep end, else 2 mm of bone lie between them.
double hu_at(const Eigen::Vector3d& p, bool joined) {
  const double depth = kLateralFace - p.x();
  const bool in_bone = depth >= 0 && depth <= 35 && std::abs(p.y()) <= 22 && std::abs(p.z()) <= 15;
  // Distance to the canal's axis, measured across it (the axis's direction normalised).
  const Eigen::Vector3d along = Eigen::Vector3d(-1, -kAnteriorPerMm, 0).normalized();
  const Eigen::Vector3d offset = p - Eigen::Vector3d(kLateralFace, 0, 0);
  const double t = offset.dot(along);
  const bool in_canal = t >= 0 && (offset - t * along).norm() < kRadius && depth <= kCanalLength && p.x() < 88;
  // The middle ear: a box 8 mm wide along x, reaching 9 mm behind the canal's deep end.
  const Eigen::Vector2d deep = axis_yz(kCanalLength);
  const double ear_near = kCanalLength + (joined ? 0 : 2);
  const bool in_ear = depth >= ear_near && depth <= ear_near + 8 && p.y() >= deep.x() - 3 && p.y() <= deep.x() + 9 &&
                      std::abs(p.z()) <= 3;
  if (in_canal || in_ear) return -1000;
  if (in_bone) return 1200;
  return p.x() < 88 ? 40 : -1000;  // soft tissue out to the skin, then air
}

// The temporal bone on `side` (+1 left, -1 right: the left one mirrored), in 0.5 mm voxels.
HeadVolume temporal_bone(int side, bool joined) {
  Volume ct;
  ct.geometry.spacing = {0.5, 0.5, 0.5};
  ct.geometry.size = {160, 120, 100};
  ct.geometry.origin = {side > 0 ? 20.0 : -99.5, -30, -25};
  ct.hu.resize(size_t(ct.geometry.voxel_count()));
  for (int k = 0; k < ct.geometry.size.z(); ++k)
    for (int j = 0; j < ct.geometry.size.y(); ++j)
      for (int i = 0; i < ct.geometry.size.x(); ++i) {
        Eigen::Vector3d p = ct.geometry.world(Eigen::Vector3d(i, j, k));
        p.x() *= side;
        ct.at(i, j, k) = int16_t(hu_at(p, joined));
      }
  const Eigen::Vector3d lo = ct.geometry.origin;
  const Eigen::Vector3d hi = ct.geometry.world((ct.geometry.size - Eigen::Vector3i::Ones()).cast<double>());
  return HeadVolume(ct, GreyCalibration{}, Eigen::Isometry3d::Identity(), FrameBox{lo, hi}, 0.5);
}

// Porion's distance from the known answer on `side`.
double porion_error(int side, bool joined) {
  const HeadVolume v = temporal_bone(side, joined);
  const auto porion = find_porion(v, Eigen::Vector3d(side * (kLateralFace - 2), 0, 0), side);
  if (!porion.position) return 1e9;
  const Eigen::Vector2d axis = axis_yz(1.5);
  const Eigen::Vector3d truth(side * kLateralFace, axis.x(), axis.y() + kRadius);
  return (*porion.position - truth).norm();
}

TEST(EarCanal, PorionIsTheTopOfAnObliqueCanalAtItsOpening) { EXPECT_LT(porion_error(+1, false), 0.6); }

// The whole canal's centre lay 2.5 mm deeper here than at the opening: along an oblique axis
// that moved porion's y.
TEST(EarCanal, AMiddleEarJoinedToTheCanalDoesNotMovePorion) { EXPECT_LT(porion_error(+1, true), 0.6); }

TEST(EarCanal, TheRightSideIsTheLeftMirrored) { EXPECT_LT(porion_error(-1, true), 0.6); }

}  // namespace
}  // namespace maxillo::landmarking
