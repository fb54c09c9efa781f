// The cartilaginous nose's region (casework/softtissue/nasal_cartilage.h): the tip's tissue inside, the
// upper lip, the cheek and the nasal cavity outside; the same points whatever the head's pose;
// nothing without its landmarks; and the tets inside given the factor.
#include "casework/softtissue/nasal_cartilage.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "softtissue/cube_mesh.h"

namespace maxillo::casework {
namespace {

// A head in the patient axes (LPS: anterior -y, superior +z, left +x), its midline at x = 0.
LandmarkSet head_landmarks() {
  return {{"PoR", {-60, 0, 100}}, {"PoL", {60, 0, 100}}, {"OrR", {-35, -75, 100}}, {"OrL", {35, -75, 100}},
          {"N", {0, -85, 140}},   {"ANS", {0, -95, 95}}, {"Sn", {0, -103, 93}},    {"Prn", {0, -119, 109}}};
}

struct Probe {
  const char* where;
  Eigen::Vector3d point;
  bool inside;
};

const Probe kProbes[] = {
    {"behind the nose tip", {0, -114, 108}, true},
    {"the ala", {12, -108, 98}, true},
    {"the dorsum over the nasal bones", {0, -95, 125}, true},
    {"the upper lip", {0, -100, 85}, false},
    {"the cheek beside the ala", {25, -100, 100}, false},
    {"the nasal cavity", {0, -85, 100}, false},
};

TEST(NasalCartilage, TheTipAndAlaeAreInsideTheLipCheekAndCavityOutside) {
  const auto region = nasal_cartilage_region(head_landmarks());
  ASSERT_TRUE(region);
  for (const auto& probe : kProbes) EXPECT_EQ(region->contains(probe.point), probe.inside) << probe.where;
}

TEST(NasalCartilage, TheRegionMovesWithTheHead) {
  const Eigen::Isometry3d pose =
      Eigen::Translation3d(30, -12, 55) * Eigen::AngleAxisd(0.35, Eigen::Vector3d(0.3, -1, 0.5).normalized());
  LandmarkSet moved = head_landmarks();
  for (auto& landmark : moved) landmark.position = pose * landmark.position;
  const auto region = nasal_cartilage_region(moved);
  ASSERT_TRUE(region);
  for (const auto& probe : kProbes) EXPECT_EQ(region->contains(pose * probe.point), probe.inside) << probe.where;
}

TEST(NasalCartilage, NoRegionWithoutItsLandmarksOrWithATipBehindThePlane) {
  for (const char* missing : {"N", "ANS", "Sn", "Prn"}) {
    LandmarkSet set = head_landmarks();
    std::erase_if(set, [&](const Landmark& l) { return l.label == missing; });
    EXPECT_FALSE(nasal_cartilage_region(set)) << missing;
  }
  LandmarkSet flat = head_landmarks();
  for (auto& landmark : flat)
    if (landmark.label == "Prn") landmark.position = {0, -80, 109};  // behind the N-ANS line
  EXPECT_FALSE(nasal_cartilage_region(flat));
}

TEST(NasalCartilage, TheTetsWhoseCentreLiesInsideTakeTheFactor) {
  auto mesh = softtissue::make_cube_mesh({10.0, 4, softtissue::HexSplit::kSixTets});
  const softtissue::RegionShape upper_half(std::vector<softtissue::RegionPlane>{{{0, 0, 5}, {0, 0, 1}}});
  EXPECT_EQ(stiffen_region(mesh, upper_half, 68.0), mesh.tet_count() / 2);
  ASSERT_EQ(mesh.stiffness.size(), size_t(mesh.tet_count()));
  for (int t = 0; t < mesh.tet_count(); ++t) {
    const bool upper = softtissue::tet_corners(mesh, t).col(2).mean() > 5;
    EXPECT_EQ(mesh.stiffness_of(t), upper ? 68.0 : 1.0);
  }
}

TEST(NasalCartilage, TheRegionsNodesAreTheCornersOfItsTets) {
  // A 10 mm cube in 4 x 4 x 4 hexes of six tets: the upper half's tets have their corners on the
  // three node layers z = 5, 7.5 and 10; none below.
  const auto mesh = softtissue::make_cube_mesh({10.0, 4, softtissue::HexSplit::kSixTets});
  const softtissue::RegionShape upper_half(std::vector<softtissue::RegionPlane>{{{0, 0, 5}, {0, 0, 1}}});
  const auto nodes = region_tet_nodes(mesh, upper_half);
  ASSERT_EQ(nodes.size(), size_t(mesh.node_count()));
  for (int i = 0; i < mesh.node_count(); ++i) EXPECT_EQ(nodes[size_t(i)], mesh.nodes(i, 2) >= 5 - 1e-9 ? 1 : 0) << i;
}

}  // namespace
}  // namespace maxillo::casework
