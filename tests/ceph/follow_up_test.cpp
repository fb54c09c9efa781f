// Cohort follow-up: the cohort CSV format and the change tables (mean ± SD, n) against
// hand-computed answers.
#include "ceph/follow_up.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace maxillo::ceph {
namespace {

// One analysis holding only ANS_X = value (other ids absent).
TimePointAnalysis point(const std::string& label, const std::string& date, std::optional<double> ans_x) {
  TimePointAnalysis tp{label, date, {}};
  Measurement m;
  m.id = "ANS_X";
  m.unit = "mm";
  m.value = ans_x;
  tp.analysis.measurements.push_back(m);
  return tp;
}

TEST(FollowUp, ChangesAreMeanAndSampleSdOverCasesWithBothTimePoints) {
  std::vector<CaseFollowUp> cohort = {
      make_follow_up("P1", {point("post", "2001-03-01", 12), point("pre", "2001-01-01", 2)}),
      make_follow_up("P2", {point("pre", "2002-01-01", 0), point("post", "2002-03-01", 8)}),
      make_follow_up("P3", {point("pre", "2003-01-01", 1), point("post", "2003-03-01", 10)}),
      make_follow_up("P4", {point("pre", "2003-01-01", 1)}),                                   // no post
      make_follow_up("P5", {point("pre", "", 1), point("post", "2004-01-01", std::nullopt)}),  // not measurable
  };
  EXPECT_EQ(cohort[0].time_points[0].label, "pre");   // ordered by date
  EXPECT_EQ(cohort[4].time_points[0].label, "post");  // undated last
  auto rows = cohort_changes(cohort, "pre", "post", {"ANS_X", "Wits"});
  ASSERT_EQ(rows.size(), 2u);
  // Changes 10, 8, 9: mean 9, sample SD 1.
  EXPECT_EQ(rows[0].n, 3);
  EXPECT_DOUBLE_EQ(*rows[0].mean, 9);
  EXPECT_DOUBLE_EQ(*rows[0].sd, 1);
  EXPECT_EQ(rows[0].unit, "mm");
  EXPECT_EQ(format_mean_sd(rows[0]), "9.0 \u00b1 1.0");
  EXPECT_EQ(rows[1].n, 0);
  EXPECT_EQ(format_mean_sd(rows[1]), "n/a");
}

TEST(CohortCsv, GroupsRowsByCaseAndTimePoint) {
  auto cohort = parse_cohort_csv(
      "case,time_point,date,label,x,y,z\n"
      "P1,pre,2001-01-01,S,0,0,20\n"
      "P1,pre,2001-01-01,N,0,-70,28\n"
      "P1,post,2001-03-01,S,0,0,20\n"
      "# comment\n"
      "P2,pre,,S,1,2,3\n",
      "cohort.csv");
  ASSERT_EQ(cohort.size(), 2u);
  ASSERT_EQ(cohort[0].time_points.size(), 2u);
  EXPECT_EQ(cohort[0].time_points[0].landmarks.size(), 2u);
  EXPECT_EQ(cohort[0].time_points[1].date, "2001-03-01");
  EXPECT_EQ(cohort[1].time_points[0].date, "");
  EXPECT_EQ(cohort[1].time_points[0].landmarks[0].position, Eigen::Vector3d(1, 2, 3));
}

TEST(CohortCsv, RejectsMalformedRowsNamingTheLine) {
  auto message = [](const char* text) {
    try {
      parse_cohort_csv(text, "c.csv");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("case,time_point,date,label,x,y,z\nP1,pre,,S,0,zero,1\n").find("line 2"), std::string::npos);
  EXPECT_NE(message("case,time_point,date,label,x,y,z\nP1,pre,,S,0,0,1\nP1,pre,,S,1,1,1\n").find("duplicate"),
            std::string::npos);
  EXPECT_NE(message("label,x,y,z\n").find("header"), std::string::npos);
  EXPECT_NE(message("case,time_point,date,label,x,y,z\nP1,pre,2001-01-01,S,0,0,1\nP1,pre,2001-02-01,N,0,0,1\n")
                .find("date differs"),
            std::string::npos);
}

}  // namespace
}  // namespace maxillo::ceph
