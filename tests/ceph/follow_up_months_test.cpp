// Dates to months (days / 30.4375) and the Wits-over-months series of the source's Fig. 10.
#include "ceph/follow_up_months.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace maxillo::ceph {
namespace {

TEST(FollowUpMonths, DaysSinceEpochOfKnownDates) {
  EXPECT_EQ(days_since_epoch("1970-01-01"), 0);
  EXPECT_EQ(days_since_epoch("1970-01-02"), 1);
  EXPECT_EQ(days_since_epoch("1969-12-31"), -1);
  EXPECT_EQ(days_since_epoch("2000-03-01"), 11017);  // 30 years incl. 7 leap days + Jan, Feb 2000 (29 days)
  EXPECT_EQ(days_since_epoch("2001-01-01"), 11323);
}

TEST(FollowUpMonths, InvalidDatesAreRefused) {
  EXPECT_TRUE(days_since_epoch("2000-02-29").has_value());  // divisible by 400: leap
  EXPECT_FALSE(days_since_epoch("1900-02-29"));             // divisible by 100: not leap
  EXPECT_FALSE(days_since_epoch("2001-02-29"));
  EXPECT_FALSE(days_since_epoch("2001-04-31"));
  EXPECT_FALSE(days_since_epoch("2001-13-01"));
  EXPECT_FALSE(days_since_epoch("2001-1-01"));
  EXPECT_FALSE(days_since_epoch("20010101"));
  EXPECT_FALSE(days_since_epoch(""));
  EXPECT_THROW(months_between("2001-02-29", "2001-03-01"), Error);
}

TEST(FollowUpMonths, MonthsAreDaysOverTheMeanGregorianMonth) {
  EXPECT_DOUBLE_EQ(kDaysPerMonth, 30.4375);
  EXPECT_DOUBLE_EQ(months_between("2001-03-15", "2001-09-15"), 184 / 30.4375);  // ~6.05
  EXPECT_DOUBLE_EQ(months_between("2001-09-15", "2001-03-15"), -184 / 30.4375);
  EXPECT_DOUBLE_EQ(months_between("2000-01-01", "2004-01-01"), 48.0);  // 1461 days: one leap cycle
  EXPECT_DOUBLE_EQ(months_between("2001-03-15", "2001-03-15"), 0.0);
}

TEST(FollowUpMonths, EndOfDistractionLabels) {
  for (const char* label : {"post", "Post", "post-distraction", "End of distraction", "EOD"})
    EXPECT_TRUE(is_end_of_distraction_label(label)) << label;
  for (const char* label : {"pre", "6M", "postop", ""}) EXPECT_FALSE(is_end_of_distraction_label(label)) << label;
}

TimePointAnalysis with_wits(const std::string& label, const std::string& date, std::optional<double> wits) {
  CephalometricAnalysis analysis;
  Measurement m;
  m.id = "Wits";
  m.value = wits;
  analysis.measurements.push_back(m);
  return {label, date, analysis};
}

TEST(FollowUpMonths, OriginIsTheEndOfDistractionSoPreIsNegative) {
  CaseFollowUp c{
      "P1",
      {with_wits("pre", "2001-01-15", -6.0), with_wits("post", "2001-03-15", 2.0), with_wits("6M", "2001-09-15", 1.5),
       with_wits("undated", "", 9.0), with_wits("12M", "2002-03-15", std::nullopt)}};
  auto series = measurement_over_months(c, "Wits");
  EXPECT_EQ(series.origin, MonthsOrigin::kEndOfDistraction);
  ASSERT_EQ(series.months.size(), 3u);  // undated and value-less points left out
  EXPECT_EQ(series.labels, (std::vector<std::string>{"pre", "post", "6M"}));
  EXPECT_DOUBLE_EQ(series.months[0], -59 / 30.4375);
  EXPECT_DOUBLE_EQ(series.months[1], 0.0);
  EXPECT_DOUBLE_EQ(series.months[2], 184 / 30.4375);
  EXPECT_EQ(series.values, (std::vector<double>{-6.0, 2.0, 1.5}));
}

TEST(FollowUpMonths, WithoutEndOfDistractionTheFirstDatedPointIsTheOrigin) {
  CaseFollowUp c{"P2", {with_wits("6M", "2002-09-01", 1.0), with_wits("first", "2002-03-01", 0.5)}};
  auto series = measurement_over_months(c, "Wits");
  EXPECT_EQ(series.origin, MonthsOrigin::kFirstTimePoint);
  EXPECT_EQ(series.labels, (std::vector<std::string>{"first", "6M"}));  // by date
  EXPECT_DOUBLE_EQ(series.months[0], 0.0);
  EXPECT_DOUBLE_EQ(series.months[1], 184 / 30.4375);
}

}  // namespace
}  // namespace maxillo::ceph
