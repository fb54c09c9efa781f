// Black-box test of `maxillo occlude` on two blocks: a block 1 mm above a slab, pulled down and
// sideways by springs, must come to rest on the slab.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <fstream>

#include "core/json.h"
#include "support/pdf_tools.h"
#include "support/run_maxillo.h"
#include "support/temporary_folder.h"

namespace {

// Closed axis-aligned box as Wavefront OBJ, outward faces (same layout as test_meshes.h).
void write_box_obj(const std::filesystem::path& path, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  std::ofstream out(path);
  for (int i = 0; i < 8; ++i)
    out << "v " << ((i & 1) ? hi.x() : lo.x()) << " " << ((i & 2) ? hi.y() : lo.y()) << " "
        << ((i & 4) ? hi.z() : lo.z()) << "\n";
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& f : faces) out << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
}

TEST(OccludeCommand, SpringsBringTheBlockToRestOnTheSlab) {
  maxillo::TemporaryFolder folder;
  write_box_obj(folder / "lower.obj", {-5, -5, -2}, {5, 5, 0});
  write_box_obj(folder / "upper.obj", {-2, -2, 1}, {2, 2, 3});
  std::ofstream(folder / "pairs.csv")
      << "ux,uy,uz,lx,ly,lz\n-2,-2,1,-1,-1.5,-0.5\n2,-2,1,3,-1.5,-0.5\n0,2,1,1,2.5,-0.5\n";
  const auto run =
      maxillo::testing::run_maxillo({"occlude", (folder / "upper.obj").string(), (folder / "lower.obj").string(),
                                     "--pairs", (folder / "pairs.csv").string(), "--out", (folder / "out").string()},
                                    folder.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::ifstream in(folder / "out" / "occlusion.json");
  const maxillo::Json result = maxillo::Json::parse(in);
  EXPECT_EQ(result["status"], "converged");
  EXPECT_NEAR(result["upper_transform"][0][3].get<double>(), 1.0, 0.01);
  EXPECT_NEAR(result["upper_transform"][1][3].get<double>(), 0.5, 0.01);
  EXPECT_NEAR(result["upper_transform"][2][3].get<double>(), -1.0, 0.06);
  EXPECT_LE(result["penetration_mm"].get<double>(), result["allowed_penetration_mm"].get<double>());
  EXPECT_EQ(result["upper"]["teeth"].size(), 1u);
  EXPECT_EQ(result["upper"]["contact_vertices"], 4);  // the block's bottom corners
  for (const char* file : {"occlusionogram.png", "upper_distances.csv", "lower_distances.csv"})
    EXPECT_TRUE(std::filesystem::exists(folder / "out" / file)) << file;
}

// With --case the occlusion is kept with an archived case, and the case's report shows it.
TEST(OccludeCommand, AnOcclusionKeptWithACaseIsInItsReport) {
  maxillo::TemporaryFolder folder;
  const auto dir = folder.path();
  ASSERT_EQ(
      maxillo::testing::run_maxillo({"sample", "--out", (dir / "sample").string(), "--spacing", "2"}, dir).exit_code,
      0);
  const std::string archive = "--archive=" + (dir / "archive").string();
  ASSERT_EQ(maxillo::testing::run_maxillo({archive, "import", (dir / "sample" / "ct").string()}, dir).exit_code, 0);
  write_box_obj(dir / "lower.obj", {-5, -5, -2}, {5, 5, 0});
  write_box_obj(dir / "upper.obj", {-2, -2, 1}, {2, 2, 3});
  std::ofstream(dir / "pairs.csv") << "ux,uy,uz,lx,ly,lz\n-2,-2,1,-1,-1.5,-0.5\n2,-2,1,3,-1.5,-0.5\n0,2,1,1,2.5,-0.5\n";
  const auto occlude = maxillo::testing::run_maxillo(
      {archive, "occlude", (dir / "upper.obj").string(), (dir / "lower.obj").string(), "--pairs",
       (dir / "pairs.csv").string(), "--no-splint", "--case", "MAXILLO-PHANTOM-001", "--out", (dir / "out").string()},
      dir);
  ASSERT_EQ(occlude.exit_code, 0) << occlude.err;
  const auto report = maxillo::testing::run_maxillo(
      {archive, "report", "MAXILLO-PHANTOM-001", "--out", (dir / "report.pdf").string()}, dir);
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string text = maxillo::testing::pdf_text(dir / "report.pdf");
  for (const char* expected : {"Occlusionogram: upper arch (left), lower arch (right)", "Contacts per tooth",
                               "Final occlusion in the anatomical frame", "not made"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
}

void write_pose(const std::filesystem::path& path, const Eigen::Vector3d& translation) {
  std::ofstream(path) << "{\"upper_transform\": [[1,0,0," << translation.x() << "],[0,1,0," << translation.y()
                      << "],[0,0,1," << translation.z() << "],[0,0,0,1]]}";
}

TEST(OccludeCompare, APureTranslationGivesItsLengthEverywhere) {
  maxillo::TemporaryFolder folder;
  write_box_obj(folder / "lower.obj", {-5, -5, -2}, {5, 5, 0});
  write_box_obj(folder / "upper.obj", {-2, -2, 0.5}, {2, 2, 2.5});
  write_pose(folder / "a.json", {0, 0, 0});
  write_pose(folder / "b.json", {0.6, 0, 0.8});  // 1 mm
  const auto run = maxillo::testing::run_maxillo(
      {"--json", "occlude", "compare", (folder / "upper.obj").string(), (folder / "lower.obj").string(),
       (folder / "a.json").string(), (folder / "b.json").string(), "--roi-mm", "1", "--map",
       (folder / "map.csv").string()},
      folder.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const maxillo::Json result = maxillo::Json::parse(run.out);
  EXPECT_EQ(result["region_vertices"], 4);  // the block's bottom corners
  for (const char* key : {"median_mm", "p90_mm", "p95_mm", "max_mm"}) EXPECT_NEAR(result[key].get<double>(), 1.0, 1e-9);
  EXPECT_TRUE(std::filesystem::exists(folder / "map.csv"));
}

TEST(OccludeAutorotate, ClosesToTheFirstContactAngle) {
  maxillo::TemporaryFolder folder;
  write_box_obj(folder / "lower.obj", {10, -5, -2}, {30, 5, 0});
  write_box_obj(folder / "upper.obj", {5, -6, 1}, {45, 6, 3});
  const auto run = maxillo::testing::run_maxillo(
      {"--json", "occlude", "autorotate", (folder / "upper.obj").string(), (folder / "lower.obj").string(), "--hinge",
       "0,-50,0,0,50,0", "--pogonion", "40,0,-10", "--out", (folder / "rotation.json").string()},
      folder.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const maxillo::Json result = maxillo::Json::parse(run.out);
  EXPECT_EQ(result["outcome"], "contact");
  EXPECT_NEAR(result["angle_deg"].get<double>(), std::asin(1.0 / 30) * 180 / M_PI, 0.01);
  EXPECT_GT(result["pogonion_mm"].get<double>(), 1.0);
  EXPECT_TRUE(std::filesystem::exists(folder / "rotation.json"));
}

TEST(OccludeCommand, WithoutPairsOrASubcommandIsAUsageError) {
  maxillo::TemporaryFolder folder;
  write_box_obj(folder / "lower.obj", {-5, -5, -2}, {5, 5, 0});
  const auto run = maxillo::testing::run_maxillo(
      {"occlude", (folder / "lower.obj").string(), (folder / "lower.obj").string(), "--out", (folder / "o").string()},
      folder.path());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--pairs"), std::string::npos) << run.err;
}

TEST(OccludeCommand, RefusesTooFewPairsNamingTheFile) {
  maxillo::TemporaryFolder folder;
  write_box_obj(folder / "lower.obj", {-5, -5, -2}, {5, 5, 0});
  write_box_obj(folder / "upper.obj", {-2, -2, 1}, {2, 2, 3});
  std::ofstream(folder / "pairs.csv") << "1,2,3,4,5,6\n";
  const auto run =
      maxillo::testing::run_maxillo({"occlude", (folder / "upper.obj").string(), (folder / "lower.obj").string(),
                                     "--pairs", (folder / "pairs.csv").string(), "--out", (folder / "out").string()},
                                    folder.path());
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("pairs.csv"), std::string::npos) << run.err;
}

}  // namespace
