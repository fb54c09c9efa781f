// Black box: the real `maxillo sample` writes a DICOM series and landmark files that match
// make_phantom, replaces an earlier series, and rejects unknown options.
#include <gtest/gtest.h>

#include <fstream>

#include "ceph/landmark_io.h"
#include "core/json.h"
#include "sample/phantom.h"
#include "support/run_command.h"
#include "support/temporary_folder.h"

namespace maxillo::test {
namespace {
namespace fs = std::filesystem;
using maxillo::testing::quote;
using maxillo::testing::run_command;

size_t count_files(const fs::path& folder) {
  size_t n = 0;
  for (const auto& entry : fs::directory_iterator(folder)) n += entry.is_regular_file();
  return n;
}

TEST(SampleCommand, WritesSeriesAndLandmarksThatMatchThePhantom) {
  TemporaryFolder folder("maxillo-sample-cmd");
  const fs::path out = folder / "phantom";
  auto run =
      run_command(std::string(MAXILLO_BINARY) + " --json sample --out " + quote(out) + " --spacing 3 --class III");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  Json summary = Json::parse(run.output);
  EXPECT_EQ(summary["skeletal_class"], "III");
  EXPECT_EQ(summary["landmarks"]["frame"], "LPS");

  PhantomSpec spec = phantom_spec_for_class(SkeletalClass::III);
  spec.spacing_mm = 3;
  const Phantom phantom = make_phantom(spec);
  EXPECT_EQ(summary["ct"]["files"].get<int>(), phantom.ct.geometry.size.z());
  EXPECT_EQ(count_files(out / "ct"), size_t(phantom.ct.geometry.size.z()));
  for (const char* name : {"landmarks.mrk.json", "landmarks.csv"}) {
    LandmarkSet read = read_landmarks(out / name);
    ASSERT_EQ(read.size(), phantom.landmarks.size()) << name;
    for (size_t i = 0; i < read.size(); ++i) {
      EXPECT_EQ(read[i].label, phantom.landmarks[i].label);
      EXPECT_LT((read[i].position - phantom.landmarks[i].position).norm(), 1e-9) << name << " " << read[i].label;
    }
  }
  // A finer run replaces the series as a whole.
  auto rerun = run_command(std::string(MAXILLO_BINARY) + " sample --out " + quote(out) + " --spacing 4");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  PhantomSpec coarse;
  coarse.spacing_mm = 4;
  EXPECT_EQ(count_files(out / "ct"), size_t(make_phantom(coarse).ct.geometry.size.z()));
  EXPECT_NE(rerun.output.find("landmarks.mrk.json"), std::string::npos);
  EXPECT_EQ(rerun.output.find("Phantom^Maxillo"), std::string::npos) << "patient name printed at info level";
}

TEST(SampleCommand, RejectsUnknownValues) {
  TemporaryFolder folder("maxillo-sample-cmd");
  for (const char* options : {"--class IV", "--class 2", "--spacing 0.1", "--spacing abc"}) {
    auto run =
        run_command(std::string(MAXILLO_BINARY) + " sample --out " + quote(folder / "x") + " " + options + " 2>&1");
    EXPECT_EQ(run.exit_code, 2) << options << ": " << run.output;
    EXPECT_FALSE(fs::exists(folder / "x" / "ct")) << options;
  }
}

}  // namespace
}  // namespace maxillo::test
