// CGAL meshing of a voxelised ball: the volume is the ball's, every tet is positive, the mesh
// respects the tet budget and has no slivers, and the same region gives the same mesh however
// busy the machine is.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include "core/error.h"
#include "softtissue/element_quality.h"
#include "tetmesh/labelled_tet_mesher.h"

namespace maxillo::tetmesh {
namespace {

// A ball of radius r (mm) centred in a cube of voxels with the given spacing and an origin that
// is not zero, so coordinates must be mapped back to the patient frame correctly.
LabelVolume ball(double radius, double spacing, uint8_t label) {
  LabelVolume v;
  const int n = int(std::ceil(2 * radius / spacing)) + 8;
  v.geometry.size = Eigen::Vector3i::Constant(n);
  v.geometry.spacing = Eigen::Vector3d::Constant(spacing);
  v.geometry.origin = Eigen::Vector3d(-100, 50, 20);
  v.labels.assign(size_t(v.geometry.voxel_count()), 0);
  const Eigen::Vector3d centre = v.geometry.world(Eigen::Vector3d::Constant((n - 1) / 2.0));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if ((v.geometry.world(Eigen::Vector3d(i, j, k)) - centre).norm() <= radius)
          v.labels[size_t(v.geometry.index(i, j, k))] = label;
  return v;
}

double total_volume(const softtissue::TetMesh& mesh) {
  double sum = 0;
  for (int t = 0; t < mesh.tet_count(); ++t) sum += softtissue::signed_volume(mesh, t);
  return sum;
}

TEST(LabelledTetMesher, MeshesABallWithItsVolumeAndGoodTets) {
  const double radius = 20;
  auto volume = ball(radius, 1.0, 3);
  TetMeshingOptions options;
  options.cell_size_mm = 4;
  auto result = mesh_label(volume, 3, options);
  const auto& mesh = result.mesh;
  ASSERT_GT(mesh.tet_count(), 500);
  EXPECT_EQ(softtissue::count_non_positive_tets(mesh), 0);
  EXPECT_NEAR(total_volume(mesh), 4.0 / 3.0 * M_PI * std::pow(radius, 3),
              0.04 * 4.0 / 3.0 * M_PI * std::pow(radius, 3));
  // Every node lies inside the ball (to the facet distance): the frame mapping is right.
  const Eigen::Vector3d centre = volume.geometry.world(Eigen::Vector3d::Constant((volume.geometry.size.x() - 1) / 2.0));
  for (int n = 0; n < mesh.node_count(); ++n) ASSERT_LT((mesh.nodes.row(n).transpose() - centre).norm(), radius + 1.5);
  auto quality = softtissue::mesh_quality(mesh);
  EXPECT_GT(quality.min_dihedral_deg, 5.0);
}

// The sliver optimisers have no time limit (labelled_tet_mesher.h): a mesh made while every core
// is kept busy equals one made before, node for node. With their former 3 s limits a loaded
// machine optimised less and meshed differently.
TEST(LabelledTetMesher, GivesTheSameMeshWhileTheMachineIsBusy) {
  const auto volume = ball(25, 0.8, 2);
  TetMeshingOptions options;
  options.cell_size_mm = 2.5;
  const auto quiet = mesh_label(volume, 2, options).mesh;
  std::atomic<bool> stop{false};
  std::vector<std::thread> busy;
  for (unsigned t = 0; t < std::max(2u, 2 * std::thread::hardware_concurrency()); ++t)
    busy.emplace_back([&stop] {
      volatile double sink = 0;
      while (!stop) sink = sink + 1;
    });
  const auto loaded = mesh_label(volume, 2, options).mesh;
  stop = true;
  for (auto& thread : busy) thread.join();
  ASSERT_EQ(quiet.node_count(), loaded.node_count());
  ASSERT_EQ(quiet.tet_count(), loaded.tet_count());
  EXPECT_TRUE(quiet.nodes == loaded.nodes);
  EXPECT_TRUE(quiet.tets == loaded.tets);
}

TEST(LabelledTetMesher, CoarsensUntilTheTetBudgetIsMet) {
  auto volume = ball(20, 1.0, 1);
  TetMeshingOptions options;
  options.cell_size_mm = 2;
  options.max_tets = 3000;
  auto result = mesh_label(volume, 1, options);
  EXPECT_LE(result.mesh.tet_count(), 3000);
  EXPECT_GT(result.attempts, 1);
  EXPECT_GT(result.cell_size_mm, 2.0);
}

TEST(LabelledTetMesher, ABudgetThatCannotBeMetIsReportedWithTheMeshKept) {
  // No mesh of a 20 mm ball whose boundary stays within 1 mm of the sphere has 5 tetrahedra.
  auto volume = ball(20, 1.0, 1);
  TetMeshingOptions options;
  options.max_tets = 5;
  auto result = mesh_label(volume, 1, options);
  EXPECT_TRUE(result.over_budget());
  EXPECT_EQ(result.tet_budget, 5);
  EXPECT_EQ(result.attempts, 6);
  EXPECT_GT(result.mesh.tet_count(), 5);
  EXPECT_FALSE(mesh_label(volume, 1, {}).over_budget());
}

TEST(LabelledTetMesher, AnEmptyRegionIsAnError) {
  auto volume = ball(5, 1.0, 1);
  EXPECT_THROW(mesh_label(volume, 7), Error);
}

}  // namespace
}  // namespace maxillo::tetmesh
