#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "softtissue/cube_mesh.h"
#include "softtissue/element_quality.h"

namespace maxillo::softtissue {
namespace {

// Every interior face must be shared by exactly two tets and the boundary must be the cube's
// 6 k^2 squares, each split into 2 triangles: the mesh is conforming.
void expect_conforming(const TetMesh& mesh, int k) {
  std::map<std::array<int, 3>, int> faces;
  for (int t = 0; t < mesh.tet_count(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> face{};
      for (int a = 0, n = 0; a < 4; ++a)
        if (a != skip) face[size_t(n++)] = mesh.tets(t, a);
      std::sort(face.begin(), face.end());
      ++faces[face];
    }
  int boundary = 0;
  for (const auto& [face, count] : faces) {
    ASSERT_LE(count, 2);
    boundary += count == 1 ? 1 : 0;
  }
  EXPECT_EQ(boundary, 12 * k * k);
}

class CubeMeshTest : public ::testing::TestWithParam<HexSplit> {};

TEST_P(CubeMeshTest, CountsVolumeOrientationAndConformity) {
  const int k = 4;
  CubeSpec spec{30.0, k, GetParam()};
  TetMesh mesh = make_cube_mesh(spec);
  EXPECT_EQ(mesh.node_count(), 125);
  EXPECT_EQ(mesh.tet_count(), k * k * k * tets_per_hex(GetParam()));
  EXPECT_EQ(count_non_positive_tets(mesh), 0);
  double volume = 0;
  for (int t = 0; t < mesh.tet_count(); ++t) volume += signed_volume(mesh, t);
  EXPECT_NEAR(volume, 30.0 * 30.0 * 30.0, 1e-9);
  expect_conforming(mesh, k);
}

INSTANTIATE_TEST_SUITE_P(Splits, CubeMeshTest, ::testing::Values(HexSplit::kFiveTets, HexSplit::kSixTets));

TEST(CubeMesh, DivisionsHitTheTargetTetCount) {
  EXPECT_EQ(cube_divisions_for_tets(105000, HexSplit::kSixTets), 26);   // 6 * 26^3 = 105456
  EXPECT_EQ(cube_divisions_for_tets(105000, HexSplit::kFiveTets), 28);  // 5 * 28^3 = 109760
  EXPECT_EQ(cube_divisions_for_tets(1, HexSplit::kSixTets), 1);
}

TEST(CubeMesh, OrientPositivelyFlipsInvertedTets) {
  TetMesh mesh = make_cube_mesh({10.0, 2, HexSplit::kSixTets});
  std::swap(mesh.tets(3, 0), mesh.tets(3, 1));
  std::swap(mesh.tets(7, 2), mesh.tets(7, 3));
  EXPECT_EQ(count_non_positive_tets(mesh), 2);
  EXPECT_EQ(orient_positively(mesh), 2);
  EXPECT_EQ(count_non_positive_tets(mesh), 0);
}

TEST(ElementQuality, RegularTetHasKnownAngles) {
  TetMesh mesh;
  mesh.nodes.resize(4, 3);
  mesh.nodes << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  mesh.tets.resize(1, 4);
  mesh.tets << 0, 1, 2, 3;
  orient_positively(mesh);
  EXPECT_NEAR(min_dihedral_angle_deg(mesh, 0), std::acos(1.0 / 3.0) * 180.0 / M_PI, 1e-9);  // 70.53
  EXPECT_NEAR(aspect_ratio(mesh, 0), 1.0, 1e-12);
}

TEST(ElementQuality, KuhnAndFiveTetSplitsHaveKnownWorstAngles) {
  // A Kuhn tet (path 000-100-110-111) has dihedral angles 90, 90, 60, 60, 45, 45 degrees.
  MeshQuality six = mesh_quality(make_cube_mesh({10.0, 3, HexSplit::kSixTets}));
  EXPECT_NEAR(six.min_dihedral_deg, 45.0, 1e-9);
  // The 5-tet split: corner tets are trirectangular (smallest angle 54.74), the central
  // one is regular (70.53).
  MeshQuality five = mesh_quality(make_cube_mesh({10.0, 3, HexSplit::kFiveTets}));
  EXPECT_NEAR(five.min_dihedral_deg, std::acos(1.0 / std::sqrt(3.0)) * 180.0 / M_PI, 1e-9);
  EXPECT_GT(six.max_aspect_ratio, five.max_aspect_ratio);
  EXPECT_GE(five.mean_aspect_ratio, 1.0);
}

TEST(NodeGraph, NeighboursAreSortedAndSymmetric) {
  TetMesh mesh = make_cube_mesh({10.0, 3, HexSplit::kFiveTets});
  NodeGraph graph = build_node_graph(mesh);
  for (int i = 0; i < mesh.node_count(); ++i) {
    EXPECT_TRUE(
        std::is_sorted(graph.neighbours.begin() + graph.row_begin(i), graph.neighbours.begin() + graph.row_end(i)));
    for (int e = graph.row_begin(i); e < graph.row_end(i); ++e) {
      int j = graph.neighbours[size_t(e)];
      EXPECT_EQ(graph.neighbours[size_t(graph.find(j, i))], i);
    }
  }
  // Corner node 0 of a Kuhn-split grid touches 3 edge neighbours and the diagonal ones.
  NodeGraph kuhn = build_node_graph(make_cube_mesh({10.0, 3, HexSplit::kSixTets}));
  int interior = 1 + 4 * (1 + 4 * 1);                                // node (1, 1, 1)
  EXPECT_EQ(kuhn.row_end(interior) - kuhn.row_begin(interior), 15);  // 14 neighbours + itself
}

}  // namespace
}  // namespace maxillo::softtissue
