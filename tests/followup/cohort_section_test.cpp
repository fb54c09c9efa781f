// The sample cohort (phantoms with known advancements) through the cohort CSV, the change tables
// and the cohort report section: the post - pre change of ANS_X is the advancement projected on
// the X axis (1 deg above Frankfort), and growing patients' Wits falls after 6 months.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "followup/ceph_sample_cohort.h"
#include "sections/cephalometry_section.h"

namespace maxillo::followup {
namespace {

std::vector<ceph::CaseFollowUp> analysed(const std::vector<ceph::CohortCase>& cases) {
  std::vector<ceph::CaseFollowUp> cohort;
  for (const auto& c : cases) {
    std::vector<ceph::TimePointAnalysis> points;
    for (const auto& tp : c.time_points)
      points.push_back(
          {tp.label, tp.date, ceph::analyse(to_sagittal(tp.landmarks, LandmarkGeometry::kAuto, {}, c.name))});
    cohort.push_back(ceph::make_follow_up(c.name, std::move(points)));
  }
  return cohort;
}

TEST(SampleCohort, KnownChangesThroughTheCsvRoundTrip) {
  auto cases = ceph::parse_cohort_csv(format_cohort_csv(sample_cohort()), "sample");
  ASSERT_EQ(cases.size(), 6u);
  auto cohort = analysed(cases);
  auto rows = ceph::cohort_changes(cohort, "pre", "post", {"ANS_X", "PNS_X", "Wits"});
  double mean = 0, squares = 0;
  auto patients = sample_cohort_patients();
  for (const auto& p : patients) mean += p.advancement_mm / double(patients.size());
  for (const auto& p : patients) squares += std::pow(p.advancement_mm - mean, 2);
  double c = std::cos(std::numbers::pi / 180);
  EXPECT_EQ(rows[0].n, 6);
  EXPECT_NEAR(*rows[0].mean, mean * c, 1e-6);
  EXPECT_NEAR(*rows[0].sd, std::sqrt(squares / 5) * c, 1e-6);
  EXPECT_NEAR(*rows[1].mean, mean * c, 1e-6);  // PNS moves with the maxilla
  EXPECT_GT(*rows[2].mean, 5);                 // Wits rises: Class III corrected
  // Growing patients (mandible still growing) lose Wits after 6 months; the others keep it.
  for (size_t i = 0; i < cohort.size(); ++i) {
    auto six = cohort[i].time_points[2].analysis.value("Wits"), late = cohort[i].time_points[4].analysis.value("Wits");
    ASSERT_TRUE(six && late);
    if (patients[i].mandibular_growth_mm_per_year > 0)
      EXPECT_LT(*late, *six - 2) << patients[i].name;
    else
      EXPECT_NEAR(*late, *six, 1e-6) << patients[i].name;
  }
}

TEST(SampleCohort, ReportSectionHasChangeTablesAndWitsTable) {
  auto cohort = analysed(sample_cohort());
  auto section = sections::cohort_follow_up_section(cohort, {{"pre", "post"}, {"post", "6M"}});
  EXPECT_EQ(section.id, "cephalometry");
  std::vector<const report::Table*> tables;
  for (const auto& block : section.blocks)
    if (const auto* t = std::get_if<report::Table>(&block)) tables.push_back(t);
  ASSERT_EQ(tables.size(), 3u);
  EXPECT_EQ(tables[0]->rows.front()[0], "PNS_X");
  EXPECT_EQ(tables[0]->rows.front()[3], "6");
  // Wits table: one row per patient, one column per time point.
  EXPECT_EQ(tables[2]->rows.size(), 6u);
  EXPECT_EQ(tables[2]->columns.size(), 6u);
  EXPECT_EQ(tables[2]->columns[5].title, "24M");
}

}  // namespace
}  // namespace maxillo::followup
