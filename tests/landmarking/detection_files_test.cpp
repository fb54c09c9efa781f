// A detection written as CSV and as 3D Slicer markups: an absent landmark keeps its row (empty
// coordinates, "missing" in the markups) and the program's own reader skips it; a flagged one
// keeps its position and says why.
#include <gtest/gtest.h>

#include "ceph/landmark_io.h"
#include "landmarking/detection_files.h"

namespace maxillo::landmarking {
namespace {

LandmarkDetection three_landmarks() {
  LandmarkDetection d;
  DetectedLandmark s{"S", Eigen::Vector3d(1.5, -20.25, 40), 0.9, {}, ""};
  DetectedLandmark orbitale{
      "OrL", Eigen::Vector3d(33, -57, 0), 0.3, {{"mirror", false, "6.2 mm from the mirror image"}}, ""};
  DetectedLandmark molar{"U6R", std::nullopt, 0, {}, "no first molar crown (8.5 to 12.5 mm long) behind the premolars"};
  d.landmarks = {s, orbitale, molar};
  return d;
}

TEST(DetectionFiles, AnAbsentLandmarkKeepsItsRowAndIsSkippedWhenReadBack) {
  const LandmarkDetection d = three_landmarks();
  const std::string csv = format_detection_csv(d);
  EXPECT_TRUE(csv.starts_with("label,x,y,z,confidence,status")) << csv;
  EXPECT_NE(csv.find("U6R,,,,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("6.2 mm from the mirror image"), std::string::npos) << csv;
  const LandmarkSet from_csv = parse_landmarks(csv, LandmarkFormat::kCsv, "detection.csv");
  ASSERT_EQ(from_csv.size(), 2u);
  EXPECT_EQ(from_csv[0].label, "S");
  EXPECT_LT((from_csv[0].position - Eigen::Vector3d(1.5, -20.25, 40)).norm(), 1e-6);
  EXPECT_EQ(from_csv[1].label, "OrL");

  const std::string markups = format_detection_markups(d);
  const Json document = Json::parse(markups);
  EXPECT_EQ(document["markups"][0]["controlPoints"][2]["positionStatus"], "missing");
  const LandmarkSet from_markups = parse_landmarks(markups, LandmarkFormat::kSlicerMarkupsJson, "detection.mrk.json");
  ASSERT_EQ(from_markups.size(), 2u);
  EXPECT_LT((from_markups[1].position - Eigen::Vector3d(33, -57, 0)).norm(), 1e-6);
}

TEST(DetectionFiles, StatusSaysOkFlaggedOrAbsent) {
  const LandmarkDetection d = three_landmarks();
  EXPECT_EQ(status_of(d.landmarks[0]), "ok");
  EXPECT_EQ(status_of(d.landmarks[1]), "flagged");
  EXPECT_EQ(status_of(d.landmarks[2]), "absent");
  EXPECT_EQ(failed_checks(d.landmarks[1]), "mirror: 6.2 mm from the mirror image");
  const Json json = detection_json(d);
  EXPECT_EQ(json["landmarks"][2]["status"], "absent");
}

}  // namespace
}  // namespace maxillo::landmarking
