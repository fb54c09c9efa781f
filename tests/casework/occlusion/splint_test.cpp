// The surgical splint on two rows of spherical "teeth" in interdigitating occlusion: each upper
// sphere rests on two lower ones, so the geometry is known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/mesh_measures.h"
#include "occlusion/splint_field.h"
#include "support/test_meshes.h"
#include "casework/occlusion/occlusion_run.h"
#include "casework/occlusion/surgical_splint.h"
#include "core/temporary_folder.h"
#include "support/run_maxillo.h"

namespace maxillo::occlusion {
namespace {

// Closed UV sphere with outward faces.
TriangleMesh make_sphere(const Eigen::Vector3d& centre, double radius, int rings = 24, int segments = 48) {
  TriangleMesh m;
  m.vertices.resize(2 + (rings - 1) * segments, 3);
  m.vertices.row(0) = (centre + Eigen::Vector3d(0, 0, radius)).transpose();
  m.vertices.row(1) = (centre - Eigen::Vector3d(0, 0, radius)).transpose();
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double polar = M_PI * r / rings, azimuth = 2 * M_PI * s / segments;
      m.vertices.row(2 + (r - 1) * segments + s) =
          (centre + radius * Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                                             std::cos(polar)))
              .transpose();
    }
  const auto ring_vertex = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
  std::vector<Eigen::Vector3i> faces;
  for (int s = 0; s < segments; ++s) {
    faces.emplace_back(0, ring_vertex(1, s), ring_vertex(1, s + 1));
    faces.emplace_back(1, ring_vertex(rings - 1, s + 1), ring_vertex(rings - 1, s));
    for (int r = 1; r + 1 < rings; ++r) {
      faces.emplace_back(ring_vertex(r, s), ring_vertex(r + 1, s), ring_vertex(r + 1, s + 1));
      faces.emplace_back(ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r, s + 1));
    }
  }
  m.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) m.faces.row(Eigen::Index(f)) = faces[f].transpose();
  return m;
}

// Lower teeth: spheres of radius 4 at x = 0, 8, 16, centres z = -4. Upper: at x = 4, 12, 20, each
// touching two lower ones (centre distance 8) except the last, which touches one.
struct Arches {
  static constexpr double kRadius = 4;
  const double upper_z = -4 + std::sqrt(64.0 - 16.0);
  TriangleMesh lower, upper;
  Arches() {
    for (int t = 0; t < 3; ++t) {
      const TriangleMesh lo = make_sphere({8.0 * t, 0, -4}, kRadius),
                         up = make_sphere({8.0 * t + 4, 0, upper_z}, kRadius);
      lower = t == 0 ? lo : testing::append(lower, lo);
      upper = t == 0 ? up : testing::append(upper, up);
    }
  }
};

TEST(DistanceToMarked, EqualsBruteForce) {
  const int width = 23, height = 17;
  std::mt19937 rng(3);
  std::vector<char> marked(size_t(width * height), 0);
  for (int k = 0; k < 9; ++k) marked[rng() % marked.size()] = 1;
  const std::vector<double> d = distance_to_marked(marked, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double nearest = 1e300;
      for (int q = 0; q < width * height; ++q)
        if (marked[size_t(q)]) nearest = std::min(nearest, std::hypot(double(x - q % width), double(y - q / width)));
      EXPECT_NEAR(d[size_t(y * width + x)], nearest, 1e-9) << x << "," << y;
    }
  EXPECT_TRUE(std::isinf(distance_to_marked(std::vector<char>(6, 0), 3, 2)[4]));
}

TEST(OcclusalPlane, LiesBetweenTheRowsFacingTheUpperArch) {
  const Arches arches;
  const DistanceField upper(arches.upper), lower(arches.lower);
  const OcclusalPlane plane = fit_occlusal_plane(upper, lower, Eigen::Isometry3d::Identity(), 2.0);
  EXPECT_GT(plane.normal.z(), 0.99);
  EXPECT_GT(std::abs(plane.u.x()), 0.99);  // along the row
  EXPECT_NEAR(plane.u.cross(plane.v).dot(plane.normal), 1.0, 1e-12);
  EXPECT_GT(plane.centre.z(), -2.0);
  EXPECT_LT(plane.centre.z(), arches.upper_z - 1.0);
}

TEST(SurgicalSplint, IsWatertightFitsBothArchesWithoutPenetratingAndKeepsItsThickness) {
  const Arches arches;
  const DistanceField upper(arches.upper), lower(arches.lower);
  SplintOptions options;  // 2 mm, imprints 1 mm, clearance 0.1 mm, voxel 0.25 mm
  const casework::Splint splint = casework::make_splint(upper, lower, Eigen::Isometry3d::Identity(), options);
  const casework::SplintReport& r = splint.report;

  const EdgeCounts edges = count_edges(splint.mesh);
  EXPECT_EQ(edges.boundary, 0);
  EXPECT_EQ(edges.non_manifold, 0);
  EXPECT_EQ(edges.inconsistent, 0);
  EXPECT_TRUE(r.watertight);
  EXPECT_EQ(connected_components(splint.mesh).face_counts.size(), 1u);
  EXPECT_GT(signed_volume(splint.mesh), 0);
  EXPECT_NEAR(r.volume_mm3, signed_volume(splint.mesh), 1e-9);

  // Touches both: the imprints lie within clearance + one voxel of each arch ...
  EXPECT_LE(r.min_distance_upper_mm, options.clearance_mm + options.voxel_mm);
  EXPECT_LE(r.min_distance_lower_mm, options.clearance_mm + options.voxel_mm);
  // ... and no splint triangle crosses a tooth triangle.
  EXPECT_EQ(r.intersecting_pairs_upper, 0);
  EXPECT_EQ(r.intersecting_pairs_lower, 0);
  const AabbTree splint_tree(splint.mesh);
  EXPECT_TRUE(splint_tree.intersecting_faces(upper.tree(), Eigen::Isometry3d::Identity()).empty());
  EXPECT_TRUE(splint_tree.intersecting_faces(lower.tree(), Eigen::Isometry3d::Identity()).empty());

  // Where no tooth is, the wafer is the whole slab: thickness + 2 x imprint depth, >= thickness.
  const double slab = options.thickness_mm + 2 * options.imprint_depth_mm;
  EXPECT_GE(r.thickness_columns, 10);
  EXPECT_GE(r.thickness_mm, options.thickness_mm);
  EXPECT_NEAR(r.thickness_mm, slab, 0.01);
  EXPECT_NEAR(casework::thickness_along(splint.mesh, {8, 5.5, 0}, splint.plane.normal), slab, 0.01);
  // The band follows the row: nothing 10 mm to the side of it, nor through a tooth's centre line.
  EXPECT_EQ(casework::thickness_along(splint.mesh, {8, 12, 0}, splint.plane.normal), 0);
}

TEST(ThicknessAlong, MeasuresABoxAcrossEachAxis) {
  const TriangleMesh box = testing::make_box({0, 0, 0}, {1, 2, 3});
  EXPECT_NEAR(casework::thickness_along(box, {0.3, 0.7, 10}, {0, 0, 1}), 3, 1e-12);
  EXPECT_NEAR(casework::thickness_along(box, {0.3, -5, 1}, {0, 1, 0}), 2, 1e-12);
  EXPECT_EQ(casework::thickness_along(box, {5, 5, 5}, {0, 0, 1}), 0);
}

// The whole occlusion run on the spheres, the upper row lifted 1 mm and pulled back by four
// springs: occlusion.json is the run's record, and it reads back as the same record.
TEST(OcclusionRun, WritesItsRecordAsOcclusionJsonThatReadsBackTheSame) {
  const Arches arches;
  const TemporaryFolder folder("occlusion-run");
  std::vector<SpringPair> pairs;
  for (double x : {4.0, 12.0, 20.0, 8.0}) pairs.push_back({{x, 0, arches.upper_z}, {x, 0, arches.upper_z}});
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  start.pretranslate(Eigen::Vector3d(0, 0, 1));
  const casework::OcclusionRun run = casework::run_occlusion(arches.upper, arches.lower, pairs, start, folder.path());

  const records::OcclusionRecord read =
      records::read_occlusion_record(Json::parse(testing::slurp(folder.path() / "occlusion.json")), "occlusion.json");
  EXPECT_EQ(records::to_json(read), records::to_json(run.record));
  EXPECT_EQ(read.format_version, records::OcclusionRecord::kFormatVersion);
  EXPECT_TRUE(read.start_transform.isApprox(start));
  EXPECT_TRUE(read.upper_transform.isApprox(run.aligned.pose));
  EXPECT_EQ(read.residual_spring_mm.size(), pairs.size());
  ASSERT_TRUE(read.upper_centroid);
  EXPECT_LT((*read.upper_centroid - Eigen::Vector3d(12, 0, arches.upper_z)).norm(),
            0.05);                         // the middle sphere's centre
  EXPECT_EQ(read.upper.teeth.size(), 3u);  // the three spheres of each row are its teeth
  EXPECT_GT(read.upper.contact_vertices, 0);
  ASSERT_TRUE(read.splint);
  EXPECT_EQ(read.splint->watertight, run.splint->report.watertight);
  for (const auto& file : read.files) EXPECT_TRUE(std::filesystem::exists(folder.path() / file)) << file;
}

}  // namespace
}  // namespace maxillo::occlusion
