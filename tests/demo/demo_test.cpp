// Black-box test of the main job: `maxillo demo` from nothing to a PDF report, checked with the
// real poppler and qpdf tools, and the report's images checked for content.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "archive/artefact_kind.h"
#include "archive/index_comparison.h"
#include "core/json.h"
#include "support/pdf_tools.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

class DemoTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    folder_ = new testing::TemporaryFolder("maxillo-demo");
    demo_ = run_command(std::string(MAXILLO_BINARY) + " demo --out " + quote(folder_->path() / "out") + " 2>&1");
  }
  static void TearDownTestSuite() { delete folder_; }
  static std::filesystem::path report() { return folder_->path() / "out" / "report.pdf"; }

  static inline testing::TemporaryFolder* folder_ = nullptr;
  static inline testing::CommandResult demo_;
};

TEST_F(DemoTest, RunsToTheEndAndWritesAReport) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  ASSERT_TRUE(std::filesystem::exists(report()));
}

TEST_F(DemoTest, ReportPassesQpdfCheck) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto check = run_command("qpdf --check " + quote(report()) + " 2>&1");
  EXPECT_EQ(check.exit_code, 0) << check.output;
}

TEST_F(DemoTest, ReportTextIsExtractable) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto text = testing::pdf_text(report());
  for (const char* expected :
       {"Phantom, Maxillo", "MAXILLO-PHANTOM-001", "Synthetic craniofacial phantom", "CT", "skin, frontal",
        "skin, lateral", "bone, oblique", "Frankfort frame", "Case contents", "SNA", "ANB", "surface-skin", "page 1 of",
        "right lateral: midline and right-sided landmarks", "left lateral: left-sided landmarks"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
}

// Issue 28: the demo works with the landmarks found on its CT, as with a patient's, and the report
// measures them against the phantom's known ones.
TEST_F(DemoTest, PlansOnTheDetectedLandmarksAndMeasuresThemAgainstTheKnownOnes) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  const auto text = testing::pdf_text(report());
  for (const char* expected : {"points found automatically", "Automatic detection against the known landmarks",
                               "Mean distance of the automatic"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  const std::string said = "landmarks found automatically: ";
  const size_t at = demo_.output.find(said);
  ASSERT_NE(at, std::string::npos) << demo_.output;
  int found = 0;
  double mean_mm = 0;
  ASSERT_EQ(std::sscanf(demo_.output.c_str() + at + said.size(),
                        "%d, mean distance from the phantom's known landmarks %lf mm", &found, &mean_mm),
            2);
  EXPECT_GE(found, 27);
  EXPECT_LT(mean_mm, 1.5);
  // The plan's frame starts at the nasion it worked with: the detected one, near the known one
  // but not it (with the known set the two would be the same point to the last bit).
  std::ifstream result_file(folder_->path() / "out" / "plan" / "plan-result.json");
  const auto origin = Json::parse(result_file).at("frame").at("origin");
  std::ifstream known_file(folder_->path() / "out" / "sample" / "landmarks.csv");
  std::string line;
  double x = 0, y = 0, z = 0;
  while (std::getline(known_file, line))
    if (std::sscanf(line.c_str(), "N,%lf,%lf,%lf", &x, &y, &z) == 3) break;
  const double distance =
      std::hypot(origin[0].get<double>() - x, origin[1].get<double>() - y, origin[2].get<double>() - z);
  EXPECT_GT(distance, 1e-6) << "the plan used the phantom's known nasion";
  EXPECT_LT(distance, 1.5);
}

TEST_F(DemoTest, ReportHasRealRenderedViews) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  EXPECT_GE(testing::pdf_page_count(report()), 1);
  auto views = testing::pdf_images(report(), folder_->path() / "images");
  EXPECT_EQ(views.size(), 34u) << "frontal, lateral and oblique views of skin and of bone, the landmarks drawn in "
                                  "three views, the augmented model (2) and each dental scan's fit (2), the "
                                  "occlusionogram, the "
                                  "splint, the Wits chart, three views of the planned skeleton, the face before, "
                                  "predicted and its displacement map (3 views each), the uncertainty band (2), the "
                                  "validation's error maps (3) and profiles expected";
  int full_frame = 0;
  for (const auto& view : views) {
    if (view.width == 1200 && (view.height == 700 || view.height == 750)) continue;  // charts: mostly white
    EXPECT_GT(view.distinct_colours, 50u) << view.file << " looks flat";
    EXPECT_GT(view.foreground_fraction, 0.05) << view.file << " looks blank";
    full_frame += view.foreground_fraction >= 0.95;
  }
  // Only the planned skeleton's close-ups of the midface may fill the frame (the skull behind).
  EXPECT_LE(full_frame, 3) << "renders without background";
}

TEST_F(DemoTest, ReportIsStoredInTheArchiveAndVerifies) {
  auto archive = folder_->path() / "out" / "archive";
  auto verify = run_command(std::string(MAXILLO_BINARY) + " --archive " + quote(archive) + " verify 2>&1");
  EXPECT_EQ(verify.exit_code, 0) << verify.output;
  auto show =
      run_command(std::string(MAXILLO_BINARY) + " --json --archive " + quote(archive) + " show case:1 2>/dev/null");
  for (const char* kind :
       {"\"report\"", "\"surface-skin\"", "\"render-bone-lateral\"", "\"landmarks\"", "\"landmark-render\""})
    EXPECT_NE(show.output.find(kind), std::string::npos) << kind << " missing in " << show.output;
}

// Issue 6 item 7: the phantom's virtual occlusion in the report, its outputs in the archive.
TEST_F(DemoTest, ReportHasTheOcclusionSectionAndItsArtefacts) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto text = testing::pdf_text(report());
  for (const char* expected : {"Occlusion", "Occlusionogram", "Guided alignment", "Contacts per tooth",
                               "Final occlusion in the anatomical frame", "pitch", "Surgical splint", "Watertight",
                               "yes (one closed piece)", "Thickness where no tooth is"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  for (const char* file : {"occlusion.json", "occlusionogram.png", "splint.stl", "splint.png"})
    EXPECT_TRUE(std::filesystem::exists(folder_->path() / "out" / "occlusion" / file)) << file;
  auto archive = folder_->path() / "out" / "archive";
  auto show =
      run_command(std::string(MAXILLO_BINARY) + " --json --archive " + quote(archive) + " show case:1 2>/dev/null");
  for (const char* kind : {"\"occlusion\"", "\"occlusionogram\"", "\"splint\""})
    EXPECT_NE(show.output.find(kind), std::string::npos) << kind << " missing in " << show.output;
}

// Issue 30: the sample's intraoral scans, each in a scanner's frame of its own, placed onto the
// CT's teeth without hands, in the report with each arch's fit pictured.
TEST_F(DemoTest, ReportHasTheDentalScansPlacedIntoTheCt) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  EXPECT_NE(demo_.output.find("dental scans placed into the CT without hands"), std::string::npos) << demo_.output;
  auto text = testing::pdf_text(report());
  for (const char* expected :
       {"Dental scans", "upper.stl (v1)", "lower.stl (v1)", "P95 mm", "confidence", "landmarks",
        "The upper arch's scan", "The lower arch's scan", "The augmented model from the front", "scanned crowns"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  auto show = run_command(std::string(MAXILLO_BINARY) + " --json --archive " +
                          quote(folder_->path() / "out" / "archive") + " dental show case:1 2>/dev/null");
  ASSERT_EQ(show.exit_code, 0) << show.output;
  const Json shown = Json::parse(show.output);
  for (const char* arch : {"upper", "lower"}) {
    ASSERT_TRUE(shown.at(arch).contains("registration")) << arch;
    EXPECT_GT(shown.at(arch).at("registration").at("on_teeth_share").get<double>(), 0.6) << arch;
  }
}

// Issue 4: the must-show plan (10 mm advancement, 6 mm widening by two trans-sinusal
// distractors) applied to the phantom, in the report with its analytic numbers.
TEST_F(DemoTest, ReportHasThePlanningSectionWithTheMustShowNumbers) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  auto text = testing::pdf_text(report());
  for (const char* expected :
       {"Surgical plan", "Planned moves", "Distraction vectors", "Distractor checks", "Activation schedule",
        "Forward simulation", "Vector divergence", "33.4\u00b0", "16.7\u00b0", "10.44 mm", "21.00",
        "All distractor checks passed", "End of consolidation", "day 100"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  std::ifstream result_file(folder_->path() / "out" / "plan" / "plan-result.json");
  auto result = Json::parse(result_file);
  EXPECT_TRUE(result.at("feasible").get<bool>());
  for (const auto& point : result.at("distraction").at("forward_simulation").at("points"))
    EXPECT_LT(point.at("error_mm").get<double>(), 0.5) << point.at("label");
  auto show = run_command(std::string(MAXILLO_BINARY) + " --json --archive " +
                          quote(folder_->path() / "out" / "archive") + " plan show case:1 2>/dev/null");
  EXPECT_NE(show.output.find("\"history\""), std::string::npos) << show.output;
}

// Issue 17: every artefact the demo stores is of a kind in the one list (archive/artefact_kind.h),
// and the demo shows every kind there is.
TEST_F(DemoTest, EveryStoredArtefactKindIsInTheOneList) {
  auto show = run_command(std::string(MAXILLO_BINARY) + " --json --archive " +
                          quote(folder_->path() / "out" / "archive") + " show case:1 2>/dev/null");
  ASSERT_EQ(show.exit_code, 0);
  std::set<ArtefactKind> stored;
  const Json shown = Json::parse(show.output);  // kept: the loop must not range over a temporary's member
  for (const auto& artefact : shown.at("item").at("artefacts")) {
    const auto kind = parse_artefact_kind(artefact.at("kind").get<std::string>());
    ASSERT_TRUE(kind) << artefact.at("kind");
    stored.insert(*kind);
  }
  EXPECT_EQ(stored.size(), std::size(kAllArtefactKinds));
}

// For a PACS: the report as a DICOM Encapsulated PDF filed into the patient's study.
TEST_F(DemoTest, ReportAsEncapsulatedPdfIsFiledIntoTheStudy) {
  ASSERT_EQ(demo_.exit_code, 0);
  auto out = folder_->path() / "out";
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(out / "archive");
  auto report = run_command(maxillo + " report MAXILLO-PHANTOM-001 --out " + quote(out / "pacs.pdf") + " --dicom " +
                            quote(out / "pacs.dcm") + " --store-dicom 2>&1");
  ASSERT_EQ(report.exit_code, 0) << report.output;
  // DCMTK's own tool takes the document back out, byte for byte.
  ASSERT_EQ(run_command("dcm2pdf " + quote(out / "pacs.dcm") + " " + quote(out / "back.pdf")).exit_code, 0);
  EXPECT_EQ(run_command("cmp -s " + quote(out / "pacs.pdf") + " " + quote(out / "back.pdf")).exit_code, 0);
  auto dump = run_command("dcmdump " + quote(out / "pacs.dcm") + " 2>/dev/null");
  EXPECT_NE(dump.output.find("EncapsulatedPDFStorage"), std::string::npos);
  EXPECT_NE(dump.output.find("[Phantom^Maxillo]"), std::string::npos);

  auto shown = Json::parse(run_command(maxillo + " --json show case:1 2>/dev/null").output);
  int reports = 0;
  for (const auto& series : shown.at("item").at("series"))
    if (series.at("role") == "report" && series.at("modality") == "DOC") ++reports;
  EXPECT_EQ(reports, 1);
}

// The demo case carries the sample cohort's first patient's dated time points: the report shows
// the follow-up table and the Wits chart (a 1200 x 700 image, wider than the 1024 px views).
TEST_F(DemoTest, ReportHasTheFollowUpTableAndTheWitsChart) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  auto text = testing::pdf_text(report());
  for (const char* expected : {"Follow-up over 5 time points", "2003-03-15", "Wits appraisal over months"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  std::vector<testing::ImageContent> charts;
  for (const auto& image : testing::pdf_images(report(), folder_->path() / "report-charts", 1100))
    if (image.width == 1200 && image.height == 700) charts.push_back(image);  // the chart's size (others differ)
  ASSERT_EQ(charts.size(), 1u);
  EXPECT_GT(charts[0].foreground_fraction, 0.01);  // axes, labels and the line on white
  EXPECT_GT(charts[0].distinct_colours, 2u);
}

TEST_F(DemoTest, WritesTheSampleCohortFollowUpReport) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  auto pdf = folder_->path() / "out" / "cohort-followup.pdf";
  ASSERT_TRUE(std::filesystem::exists(pdf));
  EXPECT_EQ(run_command("qpdf --check " + quote(pdf) + " >/dev/null 2>&1").exit_code, 0);
  auto text = testing::pdf_text(pdf);
  for (const char* expected :
       {"Cohort follow-up: 6 patients", "Change pre to post", "Change post to 6M", "Stability from post to 6M",
        "Wits appraisal (mm) per patient", "Wits appraisal over months"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  // A cohort's report, not a patient's (issue 17): its own title, no empty patient fields.
  EXPECT_NE(text.find("Cohort follow-up\n"), std::string::npos);
  for (const char* absent : {"Consultation report", "Patient ID", "Birth date"})
    EXPECT_EQ(text.find(absent), std::string::npos) << "should not be there: " << absent;
  auto images = testing::pdf_images(pdf, folder_->path() / "cohort-charts", 1100);
  ASSERT_EQ(images.size(), 1u);  // the chart, one line per patient
  EXPECT_GT(images[0].distinct_colours, 6u);
}

// The clinic's path: the scan arrives from the (simulated) scanner over DICOM, which the report's
// series table says, and the report leaves for the (simulated) PACS as an Encapsulated PDF in one
// of the case's studies.
TEST_F(DemoTest, TheScanArrivesAndTheReportLeavesOverDicom) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  EXPECT_NE(testing::pdf_text(report()).find("over DICOM from DEMO-CT (1 series)"), std::string::npos);
  const auto list = [](const std::filesystem::path& archive, const std::string& what) {
    return Json::parse(run_command(std::string(MAXILLO_BINARY) + " --json --archive " + quote(archive) + " list " +
                                   what + " 2>/dev/null")
                           .output);
  };
  const auto pacs = folder_->path() / "out" / "pacs";
  int reports = 0;
  for (const auto& series : list(pacs, "series")) reports += series.at("modality").get<std::string>() == "DOC";
  EXPECT_EQ(reports, 1);
  std::set<std::string> scan_studies;
  for (const auto& study : list(folder_->path() / "out" / "archive", "studies"))
    scan_studies.insert(study.at("study_uid").get<std::string>());
  const auto pacs_studies = list(pacs, "studies");
  ASSERT_EQ(pacs_studies.size(), 1u);
  EXPECT_TRUE(scan_studies.count(pacs_studies[0].at("study_uid").get<std::string>()))
      << "the report is filed in one of the case's studies";
}

// The same phantom is the same scan (UIDs derived from it): a second demo into the same folder
// re-imports nothing and reuses the stored surfaces.
TEST_F(DemoTest, SecondRunIsIdempotent) {
  ASSERT_EQ(demo_.exit_code, 0);
  auto again = run_command(std::string(MAXILLO_BINARY) + " --json demo --out " + quote(folder_->path() / "out") +
                           " 2>/dev/null");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  auto summary = Json::parse(again.output);
  EXPECT_EQ(summary.at("received_over_dicom"), 0);
  EXPECT_GT(summary.at("already_archived").get<int>(), 100);
  EXPECT_EQ(summary.at("surfaces_reused"), true);
  // The dental scans' fits are the stored ones, and lie where the scans were taken: within a
  // third of the phantom's 1 mm voxel (tests/casework/case_dental_scans_test.cpp says why).
  for (const char* arch : {"upper", "lower"})
    EXPECT_LT(summary.at("dental_scans").at(arch).at("distance_from_truth_mm").get<double>(), 0.35) << arch;
  auto series = run_command(std::string(MAXILLO_BINARY) + " --json --archive " +
                            quote(folder_->path() / "out" / "archive") + " list series 2>/dev/null");
  int ct_series = 0;
  for (const auto& entry : Json::parse(series.output)) ct_series += entry.at("modality") == "CT";
  EXPECT_EQ(ct_series, 2) << series.output;  // the phantom and its synthetic post-operative CT, once each
}

}  // namespace
}  // namespace maxillo

namespace maxillo {
namespace {

// Issue 3: the predicted face for the plan, in the report, with its numbers.
TEST_F(DemoTest, ReportHasTheSoftTissuePrediction) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto text = testing::pdf_text(report());
  for (const char* expected : {"Soft-tissue prediction", "mass tensor model", "tetrahedra", "smallest dihedral angle",
                               "joined to moved bone", "Pre-operative, right lateral", "Predicted, right lateral",
                               "Displacement, right lateral", "Uncertainty band", "Sn", "Ls", "PogS",
                               // issue 34: the profile judged against published Le Fort I series
                               "Plausibility: how far the predicted profile", "(read at A)",
                               "nose tip, pronasale (Prn)", "Rosen 1988", "The model's edges"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  for (const char* file :
       {"soft-tissue/predicted-skin.vtp", "soft-tissue/soft-tissue-model.vtu", "soft-tissue/simulation.json"})
    EXPECT_TRUE(std::filesystem::exists(folder_->path() / "out" / file)) << file;
  // Issue 17: the prediction reuses the moves `plan apply` stored instead of applying the plan again.
  std::ifstream simulation_file(folder_->path() / "out" / "soft-tissue" / "simulation.json");
  EXPECT_EQ(Json::parse(simulation_file)["plan_application"], "stored");
}

// Issue 4: osteotomies, the transfer model and the planned skeleton's renders.
TEST_F(DemoTest, PlanWritesTheTransferModelAndSegments) {
  const auto plan = folder_->path() / "out" / "plan";
  for (const char* file : {"transfer-model.stl", "planned-maxilla.stl", "planned-cranium.stl", "plan-lateral.png"})
    EXPECT_TRUE(std::filesystem::exists(plan / file)) << file;
  auto text = testing::pdf_text(report());
  for (const char* expected :
       {"Osteotomies: bone segments", "maxilla", "Transfer model", "Printable", "Planned skeleton"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
}

}  // namespace
}  // namespace maxillo

namespace maxillo {
namespace {

// Issue 7: the prediction validated against a synthetic post-operative CT, in the report and in
// the nightly summary.
TEST_F(DemoTest, ReportHasTheValidationAndTheNightlySummary) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto text = testing::pdf_text(report());
  for (const char* expected : {"Validation", "mutual information", "Closest-point distance", "Corresponding-point",
                               "lower lip", "upper lip", "cheeks", "Error map, frontal", "Mid-sagittal profiles"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing text: " << expected;
  const auto out = folder_->path() / "out";
  for (const char* file : {"validation/error-map-frontal.png", "validation/profile.png", "validation/validation.json",
                           "postop/truth.json", "nightly/validation-summary.pdf"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  const auto summary = out / "nightly" / "validation-summary.pdf";
  EXPECT_GE(testing::pdf_page_count(summary), 2);
  EXPECT_NE(testing::pdf_text(summary).find("Validation summary"), std::string::npos);
  // The "Cases" heading opens the page of the first case (issue 17: it stood alone at the foot of
  // the page before). pdftotext separates pages with a form feed.
  const std::string summary_text = testing::pdf_text(summary);
  const size_t cases = summary_text.find("Cases\n");
  ASSERT_NE(cases, std::string::npos);
  const size_t page_start = summary_text.rfind('\f', cases), page_end = summary_text.find('\f', cases);
  ASSERT_NE(page_start, std::string::npos) << "Cases is not on the first page";
  EXPECT_NE(summary_text.substr(page_start, page_end - page_start).find("Closest-point distance"), std::string::npos)
      << "the first case is on the page of its heading";
}

}  // namespace
}  // namespace maxillo

namespace maxillo {
namespace {

// Issue 14: the demo archive's index deleted and rebuilt from the object store alone gives back
// every table row for row (ids, cases, roles, artefacts, their derivation keys and times).
TEST_F(DemoTest, ItsArchiveIndexIsRebuiltExactlyFromTheObjectStore) {
  ASSERT_EQ(demo_.exit_code, 0) << demo_.output;
  const auto original = folder_->path() / "out" / "archive";
  const auto copy = folder_->path() / "archive-copy";
  std::filesystem::copy(original, copy, std::filesystem::copy_options::recursive);
  std::filesystem::remove(copy / "index.sqlite");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(copy);
  auto refused = run_command(maxillo + " list 2>&1");
  EXPECT_EQ(refused.exit_code, 46) << refused.output;
  auto rebuilt = run_command(maxillo + " archive rebuild-index 2>&1");
  ASSERT_EQ(rebuilt.exit_code, 0) << rebuilt.output;
  auto differences = compare_index_files(original / "index.sqlite", copy / "index.sqlite");
  for (const auto& difference : differences) ADD_FAILURE() << difference.describe();
  auto kinds = run_command("sqlite3 " + quote(copy / "index.sqlite") + " 'SELECT DISTINCT kind FROM artefacts'").output;
  for (const char* kind : {"report", "surface-skin", "landmarks", "plan", "validation", "validation-distances"})
    EXPECT_NE(kinds.find(std::string(kind) + "\n"), std::string::npos) << kind << " not among " << kinds;
  auto verify = run_command(maxillo + " verify 2>&1");
  EXPECT_EQ(verify.exit_code, 0) << verify.output;
}

}  // namespace
}  // namespace maxillo
