// `maxillo landmarks detect` end to end: a sample CT folder in, the table, the CSV (label,x,y,z
// first, read back by the program's own landmark reader) and the 3D Slicer markups out.
#include <gtest/gtest.h>

#include "ceph/landmark_io.h"
#include "core/json.h"
#include "support/run_maxillo.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

TEST(LandmarksCommand, DetectsTheSamplesLandmarksIntoCsvAndMarkups) {
  testing::TemporaryFolder folder("landmarks-command");
  ASSERT_EQ(testing::run_maxillo({"sample", "--out", (folder / "ph").string()}, folder.path()).exit_code, 0);
  const auto csv = testing::run_maxillo(
      {"landmarks", "detect", (folder / "ph" / "ct").string(), "--out", (folder / "found.csv").string()},
      folder.path());
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_NE(csv.out.find("head frame: Frankfort horizontal"), std::string::npos) << csv.out;
  const std::string text = testing::slurp(folder / "found.csv");
  EXPECT_TRUE(text.starts_with("label,x,y,z,confidence,status")) << text.substr(0, 80);
  // Read back as a landmark file, near the sample's own landmarks (absent rows, which the sample
  // has none of, are skipped: detection_files_test.cpp).
  const LandmarkSet found = read_landmarks(folder / "found.csv");
  const LandmarkSet truth = read_landmarks(folder / "ph" / "landmarks.csv");
  EXPECT_EQ(found.size(), 29u);
  for (const char* label : {"S", "N", "ANS", "PNS", "Me", "U6R", "L6L"})
    EXPECT_LT((*find_landmark(found, label) - *find_landmark(truth, label)).norm(), 1.2) << label;

  const auto json = testing::run_maxillo({"landmarks", "detect", (folder / "ph" / "ct").string(), "--only", "S,N,U6R",
                                          "--out", (folder / "found.mrk.json").string(), "--json"},
                                         folder.path());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const Json document = Json::parse(json.out);
  ASSERT_EQ(document["landmarks"].size(), 3u);
  EXPECT_EQ(document["landmarks"][2]["label"], "U6R");
  EXPECT_EQ(document["landmarks"][2]["status"], "ok");
  EXPECT_EQ(read_landmarks(folder / "found.mrk.json").size(), 3u);

  const auto unknown =
      testing::run_maxillo({"landmarks", "detect", (folder / "ph" / "ct").string(), "--only", "Xx"}, folder.path());
  EXPECT_NE(unknown.exit_code, 0);
  EXPECT_NE(unknown.err.find("unknown landmark label 'Xx'"), std::string::npos) << unknown.err;
}

// A cone-beam sample (grey values that are not HU, cupping, metal streaks, a cut field) through
// the same command: the grey scale and the cupping found are said, and the points the field
// holds come out near the sample's own.
TEST(LandmarksCommand, ReadsAConeBeamSample) {
  testing::TemporaryFolder folder("landmarks-command-cbct");
  ASSERT_EQ(
      testing::run_maxillo(
          {"sample", "--vary", "--cbct", "--patient-id", "BENCH-003", "--out", (folder / "cb").string()}, folder.path())
          .exit_code,
      0);
  const auto run = testing::run_maxillo(
      {"landmarks", "detect", (folder / "cb" / "ct").string(), "--out", (folder / "found.csv").string(), "--json"},
      folder.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json document = Json::parse(run.out);
  EXPECT_EQ(document["method"], "maxillo-landmarks 2");
  EXPECT_NE(document["grey_values"].get<std::string>().find("mapped to -1000 and 40 HU"), std::string::npos)
      << document["grey_values"];
  EXPECT_GT(document["cone_beam_cupping_undone"].get<double>(), 0.05);
  const LandmarkSet found = read_landmarks(folder / "found.csv");
  const LandmarkSet truth = read_landmarks(folder / "cb" / "landmarks.csv");
  for (const char* label : {"S", "N", "ANS", "PNS", "Me", "OrL", "PoR", "U6R"}) {
    if (find_landmark(truth, label) && find_landmark(found, label)) {
      EXPECT_LT((*find_landmark(found, label) - *find_landmark(truth, label)).norm(), 1.5) << label;
    }
  }
  EXPECT_GE(found.size(), 24u);
}

}  // namespace
}  // namespace maxillo
