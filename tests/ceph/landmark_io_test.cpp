// Landmark files: round trips in every format, RAS <-> LPS, malformed inputs rejected with the
// line (or control point) and the reason.
#include "ceph/landmark_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "core/error.h"
#include "core/json.h"

namespace maxillo {
namespace {
namespace fs = std::filesystem;

LandmarkSet sample_set() {
  return {{"S", {0, 0, 20}},
          {"N", {0, -69.479, 28.531}},
          {"OrR", {-33, -56.93125, 1e-7}},
          {"A point (label with spaces)", {0.1, -68.4665, -29.4601}},
          {"U6L", {29.08, -48.46, -47.72}}};
}

void expect_same(const LandmarkSet& a, const LandmarkSet& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].label, b[i].label);
    EXPECT_EQ(a[i].position, b[i].position) << a[i].label;  // exact: shortest round-trip digits
  }
}

// Expects parse to fail with kBadValue and every fragment in the message.
void expect_rejected(std::string_view text, LandmarkFormat format, std::initializer_list<std::string> fragments) {
  try {
    parse_landmarks(text, format, "case.file");
    FAIL() << "accepted: " << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kBadValue);
    std::string message = e.what();
    EXPECT_NE(message.find("case.file"), std::string::npos) << message;
    for (const auto& f : fragments)
      EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
  }
}

class LandmarkFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("maxillo-landmarks-" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(LandmarkFiles, RoundTripInEveryFormat) {
  for (const char* name : {"set.mrk.json", "set.fcsv", "set.csv", "SET.CSV"}) {
    write_landmarks(folder_ / name, sample_set());
    expect_same(read_landmarks(folder_ / name), sample_set());
  }
}

TEST(LandmarkIo, FormatChosenByExtension) {
  EXPECT_EQ(landmark_format_for("a/b.mrk.json"), LandmarkFormat::kSlicerMarkupsJson);
  EXPECT_EQ(landmark_format_for("b.json"), LandmarkFormat::kSlicerMarkupsJson);
  EXPECT_EQ(landmark_format_for("b.fcsv"), LandmarkFormat::kSlicerFcsv);
  EXPECT_EQ(landmark_format_for("b.csv"), LandmarkFormat::kCsv);
  for (const char* bad : {"b.txt", "b", "b.csv.bak", ".csv"}) EXPECT_THROW(landmark_format_for(bad), Error) << bad;
  try {
    write_landmarks("/tmp/landmarks.xyz", sample_set());
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("landmarks.xyz"), std::string::npos);
  }
}

TEST(LandmarkIo, LabelsThatCannotBeWrittenAsCsvAreRejected) {
  LandmarkSet bad = {{"A, point", {0, 0, 0}}};
  EXPECT_THROW(format_landmarks(bad, LandmarkFormat::kCsv), Error);
  EXPECT_THROW(format_landmarks(bad, LandmarkFormat::kSlicerFcsv), Error);
  EXPECT_EQ(parse_landmarks(format_landmarks(bad, LandmarkFormat::kSlicerMarkupsJson),
                            LandmarkFormat::kSlicerMarkupsJson, "j")
                .at(0)
                .label,
            "A, point");
}

TEST(LandmarkIo, MarkupsJsonDeclaresLpsAndSchema) {
  Json doc = Json::parse(format_landmarks(sample_set(), LandmarkFormat::kSlicerMarkupsJson));
  EXPECT_NE(doc["@schema"].get<std::string>().find("markups-schema-v1.0.3.json"), std::string::npos);
  EXPECT_EQ(doc["markups"][0]["coordinateSystem"], "LPS");
  EXPECT_EQ(doc["markups"][0]["type"], "Fiducial");
  EXPECT_EQ(doc["markups"][0]["controlPoints"].size(), 5u);
}

TEST(LandmarkIo, RasMarkupsAreConvertedToLps) {
  Json doc = Json::parse(format_landmarks(sample_set(), LandmarkFormat::kSlicerMarkupsJson));
  doc["markups"][0]["coordinateSystem"] = "RAS";
  for (auto& p : doc["markups"][0]["controlPoints"]) {
    p["position"][0] = -p["position"][0].get<double>();
    p["position"][1] = -p["position"][1].get<double>();
  }
  expect_same(parse_landmarks(doc.dump(), LandmarkFormat::kSlicerMarkupsJson, "ras.mrk.json"), sample_set());
}

TEST(LandmarkIo, FcsvCoordinateSystemsIncludingLegacyCodes) {
  const std::string body = "vtkMRMLMarkupsFiducialNode_0,10,-20,30,0,0,0,1,1,1,0,N,,\n";
  const std::string columns = "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n";
  const Eigen::Vector3d lps(10, -20, 30), from_ras(-10, 20, 30);
  auto parse = [&](const std::string& header) {
    return parse_landmarks(header + columns + body, LandmarkFormat::kSlicerFcsv, "x.fcsv").at(0).position;
  };
  EXPECT_EQ(parse("# CoordinateSystem = LPS\n"), lps);
  EXPECT_EQ(parse("# CoordinateSystem = 1\n"), lps);
  EXPECT_EQ(parse("# CoordinateSystem = RAS\n"), from_ras);
  EXPECT_EQ(parse("# CoordinateSystem = 0\n"), from_ras);
  EXPECT_EQ(parse(""), from_ras);  // no declaration: Slicer's historical RAS
  // Columns in another order are followed.
  auto moved = parse_landmarks("# CoordinateSystem = LPS\n# columns = label,z,y,x\nGo,3,2,1\n",
                               LandmarkFormat::kSlicerFcsv, "y.fcsv");
  EXPECT_EQ(moved.at(0).label, "Go");
  EXPECT_EQ(moved.at(0).position, Eigen::Vector3d(1, 2, 3));
}

TEST(LandmarkIo, CsvHeaderIsOptionalAndCommentsSkipped) {
  auto with = parse_landmarks("label,x,y,z\nS,1,2,3\n", LandmarkFormat::kCsv, "a.csv");
  auto without = parse_landmarks("# phantom\n\nS, 1 ,2,3\n", LandmarkFormat::kCsv, "b.csv");
  expect_same(with, without);
  EXPECT_EQ(with.at(0).position, Eigen::Vector3d(1, 2, 3));
}

TEST(LandmarkIo, MalformedCsvNamesLineAndReason) {
  expect_rejected("label,x,y,z\nS,1,2,3\nN,1,2\n", LandmarkFormat::kCsv, {"line 3", "expected 4 columns"});
  expect_rejected("S,1,2,3\nN,1,abc,3\n", LandmarkFormat::kCsv, {"line 2", "coordinate y", "abc"});
  expect_rejected("S,1,2,3\nN,1,2.5x,3\n", LandmarkFormat::kCsv, {"line 2", "not a number"});
  expect_rejected("S,1,2,3\n\nS,4,5,6\n", LandmarkFormat::kCsv, {"line 3", "duplicate label 'S'"});
  expect_rejected(",1,2,3\n", LandmarkFormat::kCsv, {"line 1", "empty label"});
  expect_rejected("S,nan,2,3\n", LandmarkFormat::kCsv, {"line 1", "coordinate x"});
}

TEST(LandmarkIo, MalformedFcsvNamesLineAndReason) {
  expect_rejected("# CoordinateSystem = IJK\n", LandmarkFormat::kSlicerFcsv, {"line 1", "coordinate system"});
  expect_rejected("# CoordinateSystem = LPS\nid0,1,2\n", LandmarkFormat::kSlicerFcsv, {"line 2", "columns"});
  expect_rejected("# CoordinateSystem = LPS\nid0,1,2,z,0,0,0,1,1,1,0,S,,\n", LandmarkFormat::kSlicerFcsv,
                  {"line 2", "coordinate z"});
  expect_rejected("# columns = id,x,y\nid0,1,2\n", LandmarkFormat::kSlicerFcsv, {"line 2", "lacks"});
}

TEST(LandmarkIo, MalformedMarkupsJsonNamesLineOrPointAndReason) {
  expect_rejected("{\n  \"markups\": [\n    {,}\n  ]\n}\n", LandmarkFormat::kSlicerMarkupsJson,
                  {"line 3", "invalid JSON"});
  expect_rejected("{\"markup\": []}", LandmarkFormat::kSlicerMarkupsJson, {"markups"});
  expect_rejected(R"({"markups":[{"coordinateSystem":"LPS","controlPoints":[{"label":"S","position":[1,2]}]}]})",
                  LandmarkFormat::kSlicerMarkupsJson, {"control point 1", "'S'", "position"});
  expect_rejected(R"({"markups":[{"controlPoints":[{"label":"S","position":[1,"2",3]}]}]})",
                  LandmarkFormat::kSlicerMarkupsJson, {"position[1]", "not a number"});
  expect_rejected(R"({"markups":[{"controlPoints":[{"position":[1,2,3]}]}]})", LandmarkFormat::kSlicerMarkupsJson,
                  {"control point 1", "label"});
  expect_rejected(
      R"({"markups":[{"controlPoints":[{"label":"S","position":[1,2,3]},{"label":"S","position":[1,2,3]}]}]})",
      LandmarkFormat::kSlicerMarkupsJson, {"control point 2", "duplicate label 'S'"});
  expect_rejected(R"({"markups":[{"coordinateSystem":"IJK","controlPoints":[]}]})", LandmarkFormat::kSlicerMarkupsJson,
                  {"markup 1", "coordinateSystem"});
}

TEST_F(LandmarkFiles, MissingFileNamesPath) {
  try {
    read_landmarks(folder_ / "absent.mrk.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kFileNotFound);
    EXPECT_NE(std::string(e.what()).find("absent.mrk.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace maxillo
