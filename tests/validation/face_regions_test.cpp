// The face region and its subregions on a schematic face: subnasale at the origin, the face looking towards -y (LPS
// anterior), landmarks at typical adult distances.
#include "validation/face_regions.h"

#include <gtest/gtest.h>

namespace maxillo::validation {
namespace {

FaceLandmarks schematic_face() {
  FaceLandmarks l;
  l.subnasale = {0, 0, 0};
  l.labrale_superius = {0, -2, -12};
  l.labrale_inferius = {0, -1, -32};
  l.soft_pogonion = {0, 2, -52};
  l.orbitale = {0, 15, 25};
  l.porion = {0, 80, 25};
  l.menton = {0, 20, -60};
  return l;
}

FaceRegion region_of(double x, double y, double z) {
  VertexMatrix p(1, 3);
  p << x, y, z;
  return classify_face_regions(p, schematic_face(), FaceAxes{})[0];
}

TEST(FaceRegions, ProfilePointsFallInTheirRegions) {
  EXPECT_EQ(region_of(0, -20, 10),
            FaceRegion::kNose);  // nose tip, above and in front of subnasale
  EXPECT_EQ(region_of(0, -2, -8), FaceRegion::kUpperLip);
  EXPECT_EQ(region_of(0, -1, -30),
            FaceRegion::kLowerLip);  // below where the lips meet (z -22)
  EXPECT_EQ(region_of(0, 2, -50),
            FaceRegion::kChin);                            // below halfway to soft pogonion (z -42)
  EXPECT_EQ(region_of(40, 10, -10), FaceRegion::kCheeks);  // lateral to the lips
  EXPECT_EQ(region_of(35, 10, 10), FaceRegion::kCheeks);   // lateral to the nose
}

TEST(FaceRegions, EyesEarsAndNeckAreOutside) {
  EXPECT_EQ(region_of(30, 10, 30),
            FaceRegion::kOutside);  // above the orbital rim
  EXPECT_EQ(region_of(60, 60, 0),
            FaceRegion::kOutside);  // less than 25 mm in front of the porion
  EXPECT_EQ(region_of(0, 50, -65),
            FaceRegion::kOutside);  // under the chin, far behind menton: neck
  EXPECT_EQ(region_of(0, 10, -80),
            FaceRegion::kOutside);  // more than 15 mm below menton
}

TEST(FaceRegions, CutsFollowTheFrameNotTheScanner) {
  // The same face turned 90 degrees about the vertical axis (looking towards +x) keeps its regions.
  FaceAxes turned;
  turned.anterior = Eigen::Vector3d::UnitX();
  turned.left = Eigen::Vector3d::UnitY();
  FaceLandmarks l = schematic_face();
  auto turn = [](const Eigen::Vector3d& p) { return Eigen::Vector3d(-p.y(), p.x(), p.z()); };
  for (Eigen::Vector3d* p :
       {&l.subnasale, &l.labrale_superius, &l.labrale_inferius, &l.soft_pogonion, &l.orbitale, &l.porion, &l.menton})
    *p = turn(*p);
  VertexMatrix points(3, 3);
  points.row(0) = turn({0, -20, 10}).transpose();
  points.row(1) = turn({0, -1, -30}).transpose();
  points.row(2) = turn({60, 60, 0}).transpose();
  const auto regions = classify_face_regions(points, l, turned);
  EXPECT_EQ(regions[0], FaceRegion::kNose);
  EXPECT_EQ(regions[1], FaceRegion::kLowerLip);
  EXPECT_EQ(regions[2], FaceRegion::kOutside);
}

TEST(FaceRegions, MaskOfTheWholeFaceIsEveryInsidePoint) {
  const std::vector regions{FaceRegion::kOutside, FaceRegion::kNose, FaceRegion::kChin};
  EXPECT_EQ(region_mask(regions, FaceRegion::kOutside), (std::vector<bool>{false, true, true}));
  EXPECT_EQ(region_mask(regions, FaceRegion::kChin), (std::vector<bool>{false, false, true}));
}

}  // namespace
}  // namespace maxillo::validation
