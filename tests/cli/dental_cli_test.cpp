// Issue 30 from the command line, as a user runs it: `maxillo dental import`, `register` and
// `show` on the archived phantom, then `maxillo occlude --case` on the case's augmented jaws, in
// its CT's frame; the wrong inputs a user makes (a scan in centimetres, occluding before the
// scans are placed) are errors that say what to do.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/json.h"
#include "mesh/mesh_io.h"
#include "support/run_maxillo.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

class DentalCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    folder_ = new testing::TemporaryFolder("maxillo-dental-cli");
    ASSERT_EQ(run({"sample", "--out", (folder_->path() / "sample").string()}).exit_code, 0);
    ASSERT_EQ(run({"import", (folder_->path() / "sample" / "ct").string()}).exit_code, 0);
  }
  static void TearDownTestSuite() { delete folder_; }
  static testing::RunResult run(std::vector<std::string> args) {
    args.insert(args.begin(), {"--archive", (folder_->path() / "archive").string()});
    return testing::run_maxillo(args, folder_->path());
  }
  static std::filesystem::path dental(const char* file) { return folder_->path() / "sample" / "dental" / file; }
  static inline testing::TemporaryFolder* folder_ = nullptr;
};

TEST_F(DentalCli, ImportRegisterShowAndOccludeTheCaseInItsCtFrame) {
  // Occluding before the scans are placed says how to place them.
  const auto early = run({"occlude", "--case", "1", "--out", (folder_->path() / "early").string()});
  EXPECT_NE(early.exit_code, 0);
  EXPECT_NE(early.err.find("dental register"), std::string::npos) << early.err;

  // A scan in centimetres is refused, naming the file, and nothing is stored.
  TriangleMesh centimetres = read_mesh(dental("lower.stl"));
  centimetres.vertices *= 0.1;
  const auto cm_file = folder_->path() / "lower-cm.stl";
  write_mesh(centimetres, cm_file);
  const auto refused = run({"dental", "import", "1", "--lower", cm_file.string()});
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.err.find("lower-cm.stl"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("centimetres"), std::string::npos) << refused.err;

  ASSERT_EQ(run({"landmarks", "detect", "1", "--store"}).exit_code, 0);
  const auto imported = run({"--json", "dental", "import", "1", "--upper", dental("upper.stl").string(), "--lower",
                             dental("lower.stl").string()});
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_EQ(Json::parse(imported.out).at("scans").size(), 2u);

  const auto registered = run({"--json", "dental", "register", "1"});
  ASSERT_EQ(registered.exit_code, 0) << registered.err;
  for (const auto& arch : Json::parse(registered.out).at("arches")) {
    EXPECT_GT(arch.at("on_teeth_share").get<double>(), 0.6) << arch;
    EXPECT_GT(arch.at("confidence").get<double>(), 0.1) << arch;
    EXPECT_EQ(arch.at("start"), "dental landmarks and principal axes");
  }
  const auto shown = run({"--json", "dental", "show", "1"});
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  const Json show = Json::parse(shown.out);
  for (const char* arch : {"upper", "lower"}) {
    EXPECT_EQ(show.at(arch).at("scans").size(), 1u) << arch;
    EXPECT_TRUE(show.at(arch).contains("registration")) << arch;
  }

  // The augmented jaws occluded where the registration put them: the springs at rest, no tooth
  // through another, the splint closed, all in the CT's frame (the occlusion's upper transform
  // stays the identity) and stored with the case.
  const auto out = folder_->path() / "occlusion";
  const auto occluded = run({"--json", "occlude", "--case", "1", "--out", out.string()});
  ASSERT_EQ(occluded.exit_code, 0) << occluded.err;
  const Json occlusion = Json::parse(occluded.out);
  EXPECT_EQ(occlusion.at("penetration_mm").get<double>(), 0.0);
  EXPECT_TRUE(occlusion.at("splint").at("watertight").get<bool>());
  EXPECT_EQ(occlusion.at("splint").at("intersecting_pairs_upper"), 0);  // the splint crosses no tooth
  EXPECT_EQ(occlusion.at("splint").at("intersecting_pairs_lower"), 0);
  EXPECT_DOUBLE_EQ(occlusion.at("splint").at("clearance_mm").get<double>(), 0.2);
  const auto& transform = occlusion.at("upper_transform");
  for (int r = 0; r < 3; ++r) EXPECT_NEAR(transform[r][3].get<double>(), 0.0, 0.05) << transform;
  EXPECT_TRUE(std::filesystem::exists(out / "splint.stl"));
  const auto stored = run({"--json", "show", "case:1"});
  for (const char* kind : {"\"occlusion\"", "\"splint\"", "\"augmented-dentition\"", "\"dental-registration\""})
    EXPECT_NE(stored.out.find(kind), std::string::npos) << kind;
}

}  // namespace
}  // namespace maxillo
