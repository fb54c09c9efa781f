// Issue 14, defects 4, 5, 6, 8, 13: numbers that are not numbers, options out of range,
// degenerate geometry and files that are not what they claim are input errors, and a rejected
// command leaves the archive exactly as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "archive_fixture.h"
#include "core/error.h"
#include "mesh/mesh_io.h"
#include "support/test_shapes.h"
#include "support/run_maxillo.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

// Everything an archive holds, as text: its rows (through the CLI), object files and journal.
std::string archive_state(const std::filesystem::path& archive, const std::filesystem::path& scratch) {
  std::string state;
  for (const char* what : {"patients", "studies", "series", "cases", "flags"})
    state += testing::run_maxillo({"--archive", archive.string(), "--json", "list", what}, scratch).out;
  state += testing::run_maxillo({"--archive", archive.string(), "--json", "show", "case:1"}, scratch).out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(archive / "objects"))
    if (entry.is_regular_file()) state += entry.path().string() + "\n";
  return state;
}

class InputChecks : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::write_series(folder / "in", 3, "P1");
    archive = folder / "archive";
    ASSERT_EQ(run({"import", (folder / "in").string()}).exit_code, 0);
  }
  testing::RunResult run(std::vector<std::string> args) {
    args.insert(args.begin(), {"--archive", archive.string()});
    return testing::run_maxillo(args, folder.path());
  }
  TemporaryFolder folder;
  std::filesystem::path archive;
};

TEST_F(InputChecks, ARejectedPlanStoresNothing) {
  const std::string before = archive_state(archive, folder.path());
  for (const char* value : {"nan", "inf", "-inf", "1e6", "1e400", "NaN"}) {
    auto result = run({"plan", "create", "case:1", "--advance", value});
    EXPECT_EQ(result.exit_code, exit_code_for(ErrorCode::kUsage)) << value << ": " << result.err;
    EXPECT_NE(result.err.find("--advance"), std::string::npos) << result.err;
  }
  std::ofstream(folder / "huge.json")
      << R"({"format_version": 1, "distraction": {"target": {"advancement_mm": 1e400}}})";
  auto huge = run({"plan", "create", "case:1", "--from", (folder / "huge.json").string()});
  EXPECT_EQ(huge.exit_code, exit_code_for(ErrorCode::kBadValue)) << huge.err;
  EXPECT_NE(huge.err.find("huge.json"), std::string::npos) << huge.err;
  EXPECT_NE(huge.err.find("distraction.target.advancement_mm"), std::string::npos) << huge.err;
  EXPECT_EQ(archive_state(archive, folder.path()), before);
  // And the case still takes a good plan afterwards.
  EXPECT_EQ(run({"plan", "create", "case:1", "--advance", "6"}).exit_code, 0);
  EXPECT_EQ(run({"plan", "show", "case:1"}).exit_code, 0);
}

// Issue 29, fault 8: `export SERIES --out ''` was an internal error (exit 60).
TEST_F(InputChecks, AnEmptyValueIsAUsageErrorNamingTheOption) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"export", "1", "--out", ""},
                                               {"report", "case:1", "--out", ""},
                                               {"export", "", "--out", "x"}}) {
    auto result = run(args);
    EXPECT_EQ(result.exit_code, exit_code_for(ErrorCode::kUsage)) << args[0] << ": " << result.err;
    EXPECT_NE(result.err.find("must not be empty"), std::string::npos) << result.err;
  }
  auto export_option = run({"export", "1", "--out", ""});
  EXPECT_NE(export_option.err.find("--out"), std::string::npos) << export_option.err;
}

TEST_F(InputChecks, SimulateOptionsHaveRanges) {
  for (std::vector<std::string> bad : {std::vector<std::string>{"--advance", "nan"},
                                       {"--advance", "1e6"},
                                       {"--max-tets", "0"},
                                       {"--max-tets", "-1"},
                                       {"--max-tets", "10"},
                                       {"--cell-mm", "-1"},
                                       {"--cell-mm", "1e-3"},
                                       {"--poisson", "nan"}}) {
    std::vector<std::string> args = {"simulate", "case:1", "--out", (folder / "sim").string()};
    args.insert(args.end(), bad.begin(), bad.end());
    auto result = run(args);
    EXPECT_EQ(result.exit_code, exit_code_for(ErrorCode::kUsage)) << bad[0] << " " << bad[1] << ": " << result.err;
    EXPECT_NE(result.err.find(bad[0]), std::string::npos) << result.err;
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "sim"));
}

TEST_F(InputChecks, CoincidentLandmarksAreAnInputErrorNamingThem) {
  std::ofstream csv(folder / "flat.csv");
  csv << "label,x,y,z\n";
  for (const char* label : {"S", "N", "A", "B", "U6", "L6", "U1", "L1", "ANS", "PNS", "Si"})
    csv << label << ",10,20,0\n";
  csv.close();
  auto result = run({"ceph", "measure", (folder / "flat.csv").string()});
  EXPECT_EQ(result.exit_code, exit_code_for(ErrorCode::kBadValue)) << result.out << result.err;
  EXPECT_NE(result.err.find("coincide"), std::string::npos) << result.err;
  EXPECT_EQ(result.out.find("SNA"), std::string::npos) << "no measurement is printed: " << result.out;
}

TEST_F(InputChecks, OcclusionRefusesNanPairsAndBytesThatAreNotAnStl) {
  write_mesh(testing::cube(10), folder / "upper.stl");
  write_mesh(testing::cube(10), folder / "lower.stl");
  std::ofstream(folder / "pairs.csv") << "ux,uy,uz,lx,ly,lz\n0,0,0,0,0,1\n1,0,0,1,0,1\nnan,1,0,0,1,1\n";
  auto nan_pairs = run({"occlude", (folder / "upper.stl").string(), (folder / "lower.stl").string(), "--pairs",
                        (folder / "pairs.csv").string(), "--out", (folder / "occ").string()});
  EXPECT_EQ(nan_pairs.exit_code, exit_code_for(ErrorCode::kBadValue)) << nan_pairs.err;
  EXPECT_NE(nan_pairs.err.find("row 4"), std::string::npos) << nan_pairs.err;

  std::mt19937 random(3);
  std::string noise(10240, '\0');
  for (auto& c : noise) c = char(random());
  std::ofstream(folder / "noise.stl", std::ios::binary) << noise;
  std::ofstream(folder / "good-pairs.csv") << "0,0,0,0,0,1\n1,0,0,1,0,1\n0,1,0,0,1,1\n";
  auto noise_result = run({"occlude", (folder / "noise.stl").string(), (folder / "lower.stl").string(), "--pairs",
                           (folder / "good-pairs.csv").string(), "--out", (folder / "occ2").string()});
  EXPECT_EQ(noise_result.exit_code, exit_code_for(ErrorCode::kBadValue)) << noise_result.err;
  EXPECT_NE(noise_result.err.find("not an STL file"), std::string::npos) << noise_result.err;
}

}  // namespace
}  // namespace maxillo
