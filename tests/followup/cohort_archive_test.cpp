// A follow-up cohort in the archive (pipeline/cohort_archive.h): CSV -> archive -> cohort round
// trip, idempotent re-import, revisions kept; the Wits chart of an archived case (stored, reused,
// a real PNG) and in the report sections; the real binary's --import-cohort, --cohort-archive and
// cohort PDF with its chart image.
#include "records/cohort_archive.h"

#include <gtest/gtest.h>

#include <fstream>
#include <variant>

#include "core/error.h"
#include "core/temporary_folder.h"
#include "followup/ceph_sample_cohort.h"
#include "sections/cephalometry_section.h"
#include "sections/wits_chart.h"
#include "render/render_views.h"
#include "sample/phantom.h"
#include "support/pdf_tools.h"
#include "support/run_maxillo.h"
#include "support/test_archive.h"

namespace maxillo::followup {
namespace {

// The sample cohort as its CSV reads back: the data the archive must return.
std::vector<ceph::CohortCase> sample_csv_data() {
  return ceph::parse_cohort_csv(format_cohort_csv(sample_cohort()), "sample.csv");
}

void expect_same_cohort(const std::vector<ceph::CohortCase>& got, const std::vector<ceph::CohortCase>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t c = 0; c < want.size(); ++c) {
    EXPECT_EQ(got[c].name, want[c].name);
    ASSERT_EQ(got[c].time_points.size(), want[c].time_points.size()) << want[c].name;
    for (std::size_t t = 0; t < want[c].time_points.size(); ++t) {
      const auto& g = got[c].time_points[t];
      const auto& w = want[c].time_points[t];
      EXPECT_EQ(g.label, w.label);
      EXPECT_EQ(g.date, w.date);
      ASSERT_EQ(g.landmarks.size(), w.landmarks.size());
      for (std::size_t i = 0; i < w.landmarks.size(); ++i) {
        EXPECT_EQ(g.landmarks[i].label, w.landmarks[i].label);
        EXPECT_EQ(g.landmarks[i].position, w.landmarks[i].position) << w.landmarks[i].label;  // exact
      }
    }
  }
}

TEST(SampleCohort, LandmarksWithoutTheVolumeEqualThePhantoms) {
  PhantomSpec spec = phantom_spec_for_class(SkeletalClass::III);
  spec.spacing_mm = 4;
  spec.maxillary_advancement_mm += 8;
  const LandmarkSet fast = make_phantom_landmarks(spec);
  const LandmarkSet full = make_phantom(spec).landmarks;
  ASSERT_EQ(fast.size(), full.size());
  for (std::size_t i = 0; i < full.size(); ++i) {
    EXPECT_EQ(fast[i].label, full[i].label);
    EXPECT_EQ(fast[i].position, full[i].position) << full[i].label;
  }
}

struct EmptyArchive {
  TemporaryFolder folder{"maxillo-cohort-test"};
  Archive archive = Archive::open(testing::archive_at(folder.path() / "archive"), OpenMode::CreateIfMissing);
};

TEST(CohortArchive, CsvToArchiveToCohortGivesTheCsvData) {
  EmptyArchive a;
  const auto data = sample_csv_data();
  const auto report = records::import_cohort(a.archive, data, "sample", {}, "sample.csv");
  EXPECT_EQ(report.cases, 6);
  EXPECT_EQ(report.sets_stored, 30);
  EXPECT_EQ(report.sets_unchanged, 0);
  expect_same_cohort(records::archived_cohort(a.archive, "sample"), data);
  // Image-less cases of patients named by the CSV, labelled by the cohort.
  ASSERT_EQ(a.archive.patients().size(), 6u);
  EXPECT_EQ(a.archive.patients()[0].patient_id, "P01");
  EXPECT_EQ(a.archive.cases()[0].label, "cohort:sample");
  EXPECT_EQ(a.archive.resolve_case("P01"), a.archive.cases()[0].id);  // the patient's only case
  EXPECT_THROW(records::archived_cohort(a.archive, "other"), Error);
}

TEST(CohortArchive, ReimportStoresNothingAndARetracedSetIsANewVersion) {
  EmptyArchive a;
  auto data = sample_csv_data();
  records::import_cohort(a.archive, data, "sample", {}, "sample.csv");
  const auto again = records::import_cohort(a.archive, data, "sample", {}, "sample.csv");
  EXPECT_EQ(again.sets_stored, 0);
  EXPECT_EQ(again.sets_unchanged, 30);
  EXPECT_EQ(a.archive.cases().size(), 6u);

  data[0].time_points[2].landmarks[0].position.x() += 0.5;  // P01 at 6M retraced
  const auto retraced = records::import_cohort(a.archive, data, "sample", {}, "sample-v2.csv");
  EXPECT_EQ(retraced.sets_stored, 1);
  expect_same_cohort(records::archived_cohort(a.archive, "sample"), data);
  const int64_t p01 = a.archive.cases()[0].id;
  EXPECT_EQ(records::landmark_history(a.archive, p01).size(), 6u);  // the first 6M set is kept
}

TEST(CohortArchive, AnalysesFromTheArchiveEqualThoseFromTheCsv) {
  EmptyArchive a;
  records::import_cohort(a.archive, sample_csv_data(), "sample", {}, "sample.csv");
  const auto cohort = records::archived_cohort_follow_up(a.archive, "sample");
  ASSERT_EQ(cohort.size(), 6u);
  const auto changes = ceph::cohort_changes(cohort, "pre", "post", {"ANS_X", "Wits"});
  // The sample advances the maxilla by 8..13 mm (mean 10.5) at the end of distraction.
  EXPECT_EQ(changes[0].n, 6);
  EXPECT_NEAR(*changes[0].mean, 10.5, 0.05);
  EXPECT_GT(*changes[1].mean, 5);  // Wits rises from Class III towards 0
}

std::size_t image_grids(const report::Section& section) {
  std::size_t n = 0;
  for (const auto& block : section.blocks) n += std::holds_alternative<report::ImageGrid>(block);
  return n;
}

TEST(WitsChart, ArchivedCaseChartIsStoredReusedAndInTheSection) {
  EmptyArchive a;
  records::import_cohort(a.archive, sample_csv_data(), "sample", {}, "sample.csv");
  const int64_t p01 = a.archive.cases()[0].id;
  const auto follow_up = records::archived_case_follow_up(a.archive, p01, "P01");
  ASSERT_TRUE(sections::has_wits_chart(follow_up));
  const auto png = sections::case_wits_chart(a.archive, p01, follow_up);
  ASSERT_TRUE(png);
  const auto image = render::read_png(*png);
  EXPECT_EQ(image.width, 1200);
  EXPECT_EQ(image.height, 700);
  const auto artefacts = a.archive.artefacts(p01).size();
  EXPECT_EQ(sections::case_wits_chart(a.archive, p01, follow_up), png);  // reused, not re-rendered
  EXPECT_EQ(a.archive.artefacts(p01).size(), artefacts);

  const auto section = sections::case_cephalometry_section(a.archive, p01);
  EXPECT_EQ(image_grids(section), 1u);
  const auto chart = sections::wits_line_chart({follow_up});
  EXPECT_EQ(chart.x_title, "months since the end of distraction");
  ASSERT_EQ(chart.series.size(), 1u);
  EXPECT_EQ(chart.series[0].xs.size(), 5u);
  EXPECT_LT(chart.series[0].xs[0], 0);  // pre-operative: before the end of distraction
}

TEST(WitsChart, OneDatedTimePointGivesNoChart) {
  ceph::CaseFollowUp single{"P", {{"pre", "2001-01-01", {}}}};
  EXPECT_FALSE(sections::has_wits_chart(single));
  EXPECT_THROW(sections::wits_line_chart({single}), Error);
}

TEST(CohortSection, StabilityAndChartOfTheSampleCohort) {
  EmptyArchive a;
  records::import_cohort(a.archive, sample_csv_data(), "sample", {}, "sample.csv");
  const auto cohort = records::archived_cohort_follow_up(a.archive, "sample");
  const std::string stability = sections::stability_summary(cohort, "post", "6M");
  EXPECT_NE(stability.find("Stability from post to 6M"), std::string::npos) << stability;
  EXPECT_NE(stability.find(": stable"), std::string::npos) << stability;  // relapse 0.2-0.8 mm
  auto png = a.folder / "wits.png";
  sections::write_wits_chart(cohort, png);
  const auto section = sections::cohort_follow_up_section(cohort, {{"pre", "post"}, {"post", "6M"}}, png);
  EXPECT_EQ(image_grids(section), 1u);
}

TEST(CohortCommand, ImportCohortThenReportItFromTheArchive) {
  TemporaryFolder scratch("maxillo-cohort-cli");
  const std::string archive = (scratch / "archive").string(), csv = (scratch / "trial.csv").string();
  ASSERT_EQ(testing::run_maxillo({"ceph", "sample-cohort", "--out", csv}, scratch.path()).exit_code, 0);
  auto first = testing::run_maxillo({"--archive", archive, "followup", "--import-cohort", csv}, scratch.path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("cohort trial: 6 cases, 30 landmark sets stored, 0 already archived"), std::string::npos)
      << first.out;
  auto second = testing::run_maxillo({"--archive", archive, "followup", "--import-cohort", csv}, scratch.path());
  EXPECT_NE(second.out.find("0 landmark sets stored, 30 already archived"), std::string::npos) << second.out;

  const auto pdf = scratch / "trial.pdf";
  auto report = testing::run_maxillo(
      {"--archive", archive, "followup", "--cohort-archive", "trial", "--pdf", pdf.string()}, scratch.path());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string text = testing::pdf_text(pdf);
  EXPECT_NE(text.find("Change pre to post"), std::string::npos);
  EXPECT_NE(text.find("Stability from post to 6M"), std::string::npos);
  EXPECT_NE(text.find("Wits appraisal over months"), std::string::npos);
  const auto images = testing::pdf_images(pdf, scratch / "images", 1000);
  ASSERT_EQ(images.size(), 1u);  // the chart
  EXPECT_EQ(images[0].width, 1200);
  EXPECT_GT(images[0].distinct_colours, 6u);  // six patients' lines on white

  auto unknown = testing::run_maxillo({"--archive", archive, "followup", "--cohort-archive", "nope"}, scratch.path());
  EXPECT_NE(unknown.exit_code, 0);
}

}  // namespace
}  // namespace maxillo::followup
