// The real binary: `maxillo ceph measure` on landmark files (3D and image pixels), `ceph add` +
// `followup CASE`, `followup --cohort` with known changes, and `ceph classify-isbi` on real data.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "archive/archive_fixture.h"
#include "ceph/landmark_io.h"
#include "core/json.h"
#include "sample/phantom.h"
#include "support/run_maxillo.h"

namespace maxillo::testing {
namespace {

LandmarkSet phantom_set(SkeletalClass c, double advancement = 0) {
  PhantomSpec spec = phantom_spec_for_class(c);
  spec.spacing_mm = 4;
  spec.maxillary_advancement_mm += advancement;
  return make_phantom(spec).landmarks;
}

TEST(CephCommand, MeasureJsonOfThePhantom) {
  TemporaryFolder scratch;
  write_landmarks(scratch / "phantom.mrk.json", phantom_set(SkeletalClass::I));
  auto run = run_maxillo({"ceph", "measure", (scratch / "phantom.mrk.json").string(), "--json"}, scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto json = Json::parse(run.out);
  std::map<std::string, Json> by_id;
  for (const auto& m : json["measurements"]) by_id[m["id"].get<std::string>()] = m;
  EXPECT_NEAR(by_id["SNA"]["value"].get<double>(), 82, 0.05);
  EXPECT_NEAR(by_id["ANB"]["value"].get<double>(), 2, 0.05);
  EXPECT_EQ(by_id["SNA"]["deviation"], "within 1 SD");
  EXPECT_TRUE(by_id["Si_X"]["value"].is_null());
  EXPECT_NE(by_id["Si_X"]["not_available"].get<std::string>().find("Si"), std::string::npos);
}

TEST(CephCommand, MeasurePixelCsvNeedsTheImageOrientation) {
  TemporaryFolder scratch;
  // ISBI image 001 (pixels, y down): SNA 83.x, SNB 81.x per the organisers' classes.
  std::ofstream(scratch / "001.csv") << "label,x,y,z\nS,832,994,0\nN,1469,1032,0\nA,1370,1643,0\nB,1364,2056,0\n";
  auto down = run_maxillo(
      {"ceph", "measure", (scratch / "001.csv").string(), "--pixel-spacing", "0.1", "--image-y-down", "--json"},
      scratch.path());
  ASSERT_EQ(down.exit_code, 0) << down.err;
  double sna = Json::parse(down.out)["measurements"][0]["value"].get<double>();
  EXPECT_GT(sna, 83.2);  // organisers' SNA class 2
  EXPECT_LT(sna, 90);
  auto bad = run_maxillo({"ceph", "measure", (scratch / "001.csv").string(), "--geometry", "sideways"}, scratch.path());
  EXPECT_EQ(bad.exit_code, 2);
}

TEST(CephCommand, AddTimePointsThenFollowUpTable) {
  TemporaryFolder scratch;
  write_series(scratch / "dicom", 3, "P9");
  auto archive = (scratch / "archive").string();
  ASSERT_EQ(run_maxillo({"--archive", archive, "import", (scratch / "dicom").string()}, scratch.path()).exit_code, 0);
  write_landmarks(scratch / "pre.mrk.json", phantom_set(SkeletalClass::III));
  write_landmarks(scratch / "post.mrk.json", phantom_set(SkeletalClass::III, 9));
  auto add_post = run_maxillo({"--archive", archive, "ceph", "add", "P9", "--time-point", "post", "--date",
                               "2003-02-01", (scratch / "post.mrk.json").string()},
                              scratch.path());
  ASSERT_EQ(add_post.exit_code, 0) << add_post.err;
  ASSERT_EQ(run_maxillo({"--archive", archive, "ceph", "add", "P9", "--time-point", "pre", "--date", "2002-12-01",
                         (scratch / "pre.mrk.json").string()},
                        scratch.path())
                .exit_code,
            0);
  auto bad_date = run_maxillo({"--archive", archive, "ceph", "add", "P9", "--time-point", "pre", "--date", "1/12/2002",
                               (scratch / "pre.mrk.json").string()},
                              scratch.path());
  EXPECT_EQ(bad_date.exit_code, 2);
  auto table = run_maxillo({"--archive", archive, "followup", "P9", "--csv"}, scratch.path());
  ASSERT_EQ(table.exit_code, 0) << table.err;
  // pre comes first (by date) although it was added second.
  auto pre_at = table.out.find(",pre,"), post_at = table.out.find(",post,");
  ASSERT_NE(pre_at, std::string::npos);
  EXPECT_LT(pre_at, post_at);
  EXPECT_NE(table.out.find(",pre,2002-12-01,SNA,deg,"), std::string::npos);
}

TEST(CephCommand, CohortChangeTableHasTheKnownMeanAndSd) {
  TemporaryFolder scratch;
  std::ofstream csv(scratch / "cohort.csv");
  csv << "case,time_point,date,label,x,y,z\n";
  // Three patients advanced 6, 8 and 10 mm: ANS_X change mean 8 cos(1 deg), SD 2 cos(1 deg).
  double advancements[] = {6, 8, 10};
  for (int i = 0; i < 3; ++i)
    for (auto [tp, date, set] : {std::tuple{"pre", "2004-01-01", phantom_set(SkeletalClass::III)},
                                 std::tuple{"post", "2004-03-01", phantom_set(SkeletalClass::III, advancements[i])}})
      for (const auto& lm : set)
        csv << "P" << i << "," << tp << "," << date << "," << lm.label << "," << lm.position.x() << ","
            << lm.position.y() << "," << lm.position.z() << "\n";
  csv.close();
  auto run = run_maxillo({"followup", "--cohort", (scratch / "cohort.csv").string(), "--csv"}, scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto line_at = run.out.find("pre,post,ANS_X,mm,3,");
  ASSERT_NE(line_at, std::string::npos) << run.out;
  double mean = 0, sd = 0;
  ASSERT_EQ(std::sscanf(run.out.c_str() + line_at, "pre,post,ANS_X,mm,3,%lf,%lf", &mean, &sd), 2);
  double c = std::cos(std::numbers::pi / 180);
  EXPECT_NEAR(mean, 8 * c, 0.01);
  EXPECT_NEAR(sd, 2 * c, 0.01);
}

TEST(CephCommand, SampleCohortReport) {
  TemporaryFolder scratch;
  auto cohort = (scratch / "cohort.csv").string(), pdf = (scratch / "cohort.pdf").string();
  ASSERT_EQ(run_maxillo({"ceph", "sample-cohort", "--out", cohort}, scratch.path()).exit_code, 0);
  auto run = run_maxillo({"followup", "--cohort", cohort, "--pdf", pdf}, scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("change pre -> post"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("P06"), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(pdf), 1000u);
  EXPECT_EQ(slurp(pdf).rfind("%PDF", 0), 0u);
}

TEST(CephCommand, ClassifyIsbiAgreesOnEveryImage) {
  auto table = std::filesystem::path(MAXILLO_SHARED_DATA) / "isbi2015-ceph/isbi2015_train_landmarks.csv";
  if (!std::filesystem::exists(table)) GTEST_SKIP() << "ISBI 2015 landmark table absent: " << table;
  TemporaryFolder scratch;
  auto run = run_maxillo({"ceph", "classify-isbi", table.string()}, scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("3.2 <= ANB <= 5.7 deg     150/150"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("150/150", run.out.find("SNB")), std::string::npos);
  EXPECT_NE(run.out.find("150/150", run.out.find("SNA  ")), std::string::npos);
}

}  // namespace
}  // namespace maxillo::testing
