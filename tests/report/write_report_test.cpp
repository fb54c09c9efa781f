#include "report/write_report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>

#include "../render/test_meshes.h"
#include "core/error.h"
#include "support/pdf_tools.h"
#include "render/anatomical_views.h"
#include "render/render_views.h"

namespace maxillo::report {
namespace {
namespace fs = std::filesystem;
using namespace maxillo::testing;

// Renders frontal, lateral and oblique views of a phantom "head" (skin over a bony box with
// a nose) into folder and returns the figures.
std::vector<Figure> render_phantom_views(const fs::path& folder) {
  using namespace render;
  auto skin = render::testing::uv_sphere({0, 0, 0}, 70, 60, 120);
  auto bone = render::testing::box({-45, -40, -50}, {45, 40, 45});
  auto nose = render::testing::uv_sphere({0, -72, 0}, 14, 30, 60);
  Scene scene{{{&bone, kBoneIvory, 1.0, {}}, {&nose, kSkinTone, 1.0, {}}, {&skin, kSkinTone, 0.4, {}}}, {}};
  std::vector<Camera> cameras;
  std::vector<Figure> figures;
  for (auto view : {StandardView::Frontal, StandardView::Lateral, StandardView::Oblique}) {
    cameras.push_back(standard_camera(view, AnatomicalFrame{}, scene_bounds(scene), 1.0));
    figures.push_back({folder / (std::string(name_of(view)) + ".png"), std::string(name_of(view)) + " view"});
  }
  auto images = render_scene(scene, cameras, {{512, 512}});
  for (std::size_t i = 0; i < images.size(); ++i) write_png(images[i], figures[i].png);
  return figures;
}

ReportModel consultation_model(const std::vector<Figure>& figures) {
  ReportModel model;
  model.patient = {"Müller-Łukasz^Zoë", "PID-0042", "19860214", "F"};
  model.case_label = "Le Fort I advancement";
  model.generated_at = "2024-05-02T14:03:11Z";
  model.program_version = "0.1.0";
  model.series = {{"20240102", "CT", "Head 0.5 mm bone kernel", 412, {0.45, 0.45, 0.5}},
                  {"20240415", "CT", "Head follow-up", 398, {0.45, 0.45, 0.5}}};
  Table measurements{{{"Point", 2, Align::Left}, {"Distance (mm)", 1, Align::Right}, {"Direction", 1.5, Align::Left}},
                     {}};
  for (int i = 1; i <= 90; ++i)
    measurements.rows.push_back(
        {"skin point " + std::to_string(i), std::to_string(i * 0.25).substr(0, 5), i % 2 ? "anterior" : "inferior"});
  model.sections = {
      {"validation",
       {Paragraph{"Distances between the predicted and the post-operative skin surfaces."},
        KeyValueBlock{{{"Mean distance", "0.8 mm"}, {"95th percentile", "2.1 mm"}}}, measurements,
        Note{"Frame: patient LPS; distances in mm, positive outside."}}},
      {"views", {ImageGrid{figures, 3}}},
  };
  return model;
}

class WriteReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("maxillo-report-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override {
    if (!std::getenv("MAXILLO_KEEP_TEST_OUTPUT")) fs::remove_all(folder_);
  }
  fs::path folder_;
};

TEST_F(WriteReportTest, ConsultationReportIsARealPdfWithEverythingInIt) {
  const auto model = consultation_model(render_phantom_views(folder_));
  const fs::path pdf = folder_ / "consultation.pdf";
  const int pages = write_report(model, load_report_template(), pdf);

  const auto check = run_command("qpdf --check " + quote(pdf));
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_GE(pages, 3);  // the 90-row table breaks across pages
  EXPECT_EQ(pdf_page_count(pdf), pages);
  EXPECT_EQ(pdf_image_count(pdf), 3) << run_command("pdfimages -list " + quote(pdf)).output;

  const auto text = pdf_text(pdf);
  for (const char* expected :
       {"Müller-Łukasz", "Zoë", "Müller-Łukasz, Zoë", "PID-0042", "1986-02-14", "female", "Le Fort I advancement",
        "Head 0.5 mm bone kernel", "0.45 × 0.45 × 0.50", "skin point 1\n", "skin point 90", "frontal view",
        "lateral view", "oblique view", "Not a diagnosis: planning aid, verify clinically", "Consultation report"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing: " << expected;
  EXPECT_NE(text.find("page " + std::to_string(pages) + " of " + std::to_string(pages)), std::string::npos);
  // Template order: patient, then views, then validation (cephalometry etc. absent: skipped).
  EXPECT_LT(text.find("Patient and imaging"), text.find("3D views"));
  EXPECT_LT(text.find("3D views"), text.find("Validation"));
  EXPECT_EQ(text.find("Cephalometry"), std::string::npos);
  EXPECT_FALSE(fs::exists(folder_ / "consultation.pdf.tmp"));
}

TEST_F(WriteReportTest, SectionMissingFromTheTemplateIsRejectedAndNothingIsWritten) {
  auto report_template = load_report_template();
  std::erase_if(report_template.sections, [](const TemplateSection& s) { return s.id == "validation"; });
  ReportModel model;
  model.patient.name = "Doe^Jane";
  model.sections = {{"validation", {Paragraph{"x"}}}};
  try {
    write_report(model, report_template, folder_ / "out.pdf");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kBadTemplate);
    EXPECT_NE(std::string(e.what()).find("'validation'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(folder_ / "out.pdf"));
}

TEST_F(WriteReportTest, MissingFigureFailsAndLeavesNoPdf) {
  ReportModel model;
  model.patient.name = "Doe^Jane";
  model.sections = {{"views", {ImageGrid{{{folder_ / "absent.png", "x"}}, 2}}}};
  EXPECT_THROW(write_report(model, load_report_template(), folder_ / "out.pdf"), Error);
  EXPECT_FALSE(fs::exists(folder_ / "out.pdf"));
  EXPECT_TRUE(fs::is_empty(folder_));
}

}  // namespace
}  // namespace maxillo::report
