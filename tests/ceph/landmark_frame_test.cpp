#include "ceph/landmark_frame.h"

#include <gtest/gtest.h>

namespace maxillo {
namespace {

TEST(LandmarkFrame, UsesThePorionsAndOrbitalesOfTheSet) {
  const LandmarkSet set = {{"N", {0, -90, 25}},    {"PoR", {-60, 10, 3}}, {"PoL", {60, 12, -2}},
                           {"OrR", {-33, -70, 0}}, {"OrL", {33, -71, 1}}, {"S", {0, -20, 20}}};
  const AnatomicalFrame from_set = anatomical_frame(set);
  const AnatomicalFrame from_points = frankfort_frame({.porion_right = Eigen::Vector3d(-60, 10, 3),
                                                       .porion_left = Eigen::Vector3d(60, 12, -2),
                                                       .orbitale_right = Eigen::Vector3d(-33, -70, 0),
                                                       .orbitale_left = Eigen::Vector3d(33, -71, 1)});
  ASSERT_EQ(from_set.source, FrameSource::Frankfort);
  EXPECT_EQ(from_set.origin, from_points.origin);
  EXPECT_EQ(from_set.anterior, from_points.anterior);
  EXPECT_EQ(from_set.superior, from_points.superior);
  EXPECT_EQ(from_set.left, from_points.left);
}

TEST(LandmarkFrame, ASetWithoutPorionsGivesThePatientAxes) {
  EXPECT_EQ(anatomical_frame(LandmarkSet{{"OrR", {-33, -70, 0}}, {"OrL", {33, -70, 0}}}).source,
            FrameSource::PatientAxes);
  EXPECT_EQ(anatomical_frame(LandmarkSet{}).source, FrameSource::PatientAxes);
}

}  // namespace
}  // namespace maxillo
