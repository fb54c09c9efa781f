// extract_surface on analytic spheres: area and enclosed volume against 4 pi r^2 and 4/3 pi r^3,
// outward normals, closure, placement in LPS, component selection.
#include "mesh/surface_extraction.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "geometry/mesh_measures.h"
#include "support/test_shapes.h"

namespace maxillo {
namespace {

constexpr double kRadius = 15;

void expect_sphere(const TriangleMesh& mesh, double radius, double tolerance) {
  EXPECT_TRUE(is_watertight(mesh));
  EXPECT_EQ(connected_components(mesh).face_counts.size(), 1u);
  EXPECT_NEAR(signed_volume(mesh) / (4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3)), 1.0, tolerance);
  EXPECT_NEAR(surface_area(mesh) / (4 * std::numbers::pi * radius * radius), 1.0, tolerance);
}

TEST(SurfaceExtraction, RawFlyingEdgesSphereMatchesTheAnalyticSizes) {
  Volume v = testing::sphere_volume(40, {19.5, 19.5, 19.5}, kRadius);
  TriangleMesh mesh = extract_surface(v, 0, {.smoothing_iterations = 0});
  expect_sphere(mesh, kRadius, 0.01);
  EXPECT_GT(signed_volume(mesh), 0) << "normals point out";
}

TEST(SurfaceExtraction, SmoothedAndDecimatedSphereStaysWithinTwoPercent) {
  Volume v = testing::sphere_volume(40, {19.5, 19.5, 19.5}, kRadius);
  TriangleMesh mesh = extract_surface(v, 0, {.smoothing_iterations = 20, .target_triangles = 2000});
  expect_sphere(mesh, kRadius, 0.02);
  EXPECT_LE(mesh.face_count(), 2200);
  EXPECT_GE(mesh.face_count(), 1500);
}

TEST(SurfaceExtraction, PlacesTheSurfaceInLpsForObliqueAndMirroredGrids) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d origin(-100, 50, 200), centre_ijk(18, 20, 21);
  for (double handedness : {1.0, -1.0}) {
    Eigen::Matrix3d direction = rotation;
    direction.col(2) *= handedness;
    Volume v = testing::sphere_volume(40, centre_ijk, kRadius, direction, origin);
    v.geometry.spacing = {0.8, 0.8, 1.2};
    // With anisotropic spacing the field is an ellipsoid of semi-axes r * spacing.
    TriangleMesh mesh = extract_surface(v, 0, {.smoothing_iterations = 0});
    const Eigen::Vector3d expected_centre = v.geometry.world(centre_ijk);
    const Eigen::Vector3d centroid = mesh.vertices.colwise().mean().transpose();
    EXPECT_LT((centroid - expected_centre).norm(), 0.1) << "handedness " << handedness;
    EXPECT_NEAR(signed_volume(mesh) / (4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3) * 0.8 * 0.8 * 1.2), 1.0,
                0.01);
    EXPECT_TRUE(is_watertight(mesh));
  }
}

TEST(SurfaceExtraction, KeepsTheLargestComponentAndDropsASmallBlob) {
  Volume v = testing::sphere_volume(48, {20, 20, 20}, kRadius);
  Volume blob = testing::sphere_volume(48, {41, 41, 41}, 3);
  for (size_t n = 0; n < v.hu.size(); ++n) v.hu[n] = std::max(v.hu[n], blob.hu[n]);
  EXPECT_EQ(
      connected_components(
          extract_surface(v, 0, {.keep_largest_components = 0, .min_component_fraction = 0, .smoothing_iterations = 0}))
          .face_counts.size(),
      2u);
  TriangleMesh largest = extract_surface(v, 0, {.keep_largest_components = 1, .smoothing_iterations = 0});
  expect_sphere(largest, kRadius, 0.01);
  // Keeping "all" components still drops pieces under 1% of the largest by default.
  TriangleMesh filtered =
      extract_surface(v, 0, {.keep_largest_components = 0, .min_component_fraction = 0.1, .smoothing_iterations = 0});
  EXPECT_EQ(connected_components(filtered).face_counts.size(), 1u);
}

TEST(SurfaceExtraction, SurfaceCutByTheGridBorderIsClosed) {
  // A sphere poking out of the volume: the padding caps it where the scan ends.
  Volume v = testing::sphere_volume(30, {15, 15, 3}, 10);
  TriangleMesh mesh = extract_surface(v, 0, {.smoothing_iterations = 0});
  EXPECT_TRUE(is_watertight(mesh));
  EXPECT_GT(signed_volume(mesh), 0);
}

TEST(SurfaceExtraction, MaskSurfaceEnclosesTheMaskVoxels) {
  Volume v = testing::sphere_volume(40, {19.5, 19.5, 19.5}, kRadius);
  LabelVolume mask{v.geometry, std::vector<uint8_t>(v.hu.size())};
  for (size_t n = 0; n < v.hu.size(); ++n) mask.labels[n] = v.hu[n] > 0 ? 7 : 0;
  TriangleMesh mesh = extract_surface(mask, 7, {.smoothing_iterations = 20});
  EXPECT_TRUE(is_watertight(mesh));
  EXPECT_NEAR(signed_volume(mesh) / (4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3)), 1.0, 0.03);
  EXPECT_EQ(extract_surface(mask, 3).face_count(), 0) << "no voxel has label 3";
}

TEST(SurfaceExtraction, NothingAboveTheIsoValueGivesAnEmptyMesh) {
  Volume v = testing::sphere_volume(10, {5, 5, 5}, 3);
  EXPECT_EQ(extract_surface(v, 2000).face_count(), 0);
}

}  // namespace
}  // namespace maxillo
