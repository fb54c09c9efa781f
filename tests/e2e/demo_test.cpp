// Black-box test of the main job: `maxillo demo` from nothing to a PDF report, checked with the
// real poppler and qpdf tools, and the report's images checked for content.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>

#include "support/run_command.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

// Reads a binary PPM (P6) that pdfimages wrote; returns the number of distinct colours
// among its pixels (capped) and the fraction of pixels differing from the corner pixel.
struct ImageContent {
  int width = 0, height = 0;
  size_t distinct_colours = 0;
  double foreground_fraction = 0;
};

ImageContent inspect_ppm(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int max_value = 0;
  ImageContent content;
  in >> magic >> content.width >> content.height >> max_value;
  in.get();
  if (magic != "P6" || max_value != 255) return content;
  std::vector<unsigned char> rgb(size_t(content.width) * content.height * 3);
  in.read(reinterpret_cast<char*>(rgb.data()), std::streamsize(rgb.size()));
  std::set<uint32_t> colours;
  size_t foreground = 0;
  for (size_t p = 0; p + 2 < rgb.size(); p += 3) {
    uint32_t colour = (rgb[p] << 16) | (rgb[p + 1] << 8) | rgb[p + 2];
    if (colours.size() < 100000) colours.insert(colour);
    if (rgb[p] != rgb[0] || rgb[p + 1] != rgb[1] || rgb[p + 2] != rgb[2]) ++foreground;
  }
  content.distinct_colours = colours.size();
  content.foreground_fraction = double(foreground) / (double(content.width) * content.height);
  return content;
}

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
  auto text = run_command("pdftotext -enc UTF-8 " + quote(report()) + " - 2>/dev/null");
  ASSERT_EQ(text.exit_code, 0);
  for (const char* expected : {"Phantom", "Synthetic craniofacial phantom", "CT", "frontal", "lateral", "oblique"})
    EXPECT_NE(text.output.find(expected), std::string::npos) << "missing text: " << expected;
}

TEST_F(DemoTest, ReportHasPagesAndRealRenderedImages) {
  ASSERT_TRUE(std::filesystem::exists(report()));
  auto info = run_command("pdfinfo " + quote(report()) + " 2>/dev/null");
  std::smatch pages;
  ASSERT_TRUE(std::regex_search(info.output, pages, std::regex("Pages:\\s+(\\d+)")));
  EXPECT_GE(std::stoi(pages[1]), 1);

  auto images_folder = folder_->path() / "images";
  std::filesystem::create_directories(images_folder);
  ASSERT_EQ(run_command("pdfimages " + quote(report()) + " " + quote(images_folder / "img")).exit_code, 0);
  int rendered_views = 0;
  for (const auto& entry : std::filesystem::directory_iterator(images_folder)) {
    if (entry.path().extension() != ".ppm") continue;
    auto content = inspect_ppm(entry.path());
    if (content.width < 256) continue;  // logos or colour bars, not views
    ++rendered_views;
    EXPECT_GT(content.distinct_colours, 50u) << entry.path() << " looks flat";
    EXPECT_GT(content.foreground_fraction, 0.05) << entry.path() << " looks blank";
    EXPECT_LT(content.foreground_fraction, 0.95) << entry.path() << " has no background";
  }
  EXPECT_GE(rendered_views, 3) << "frontal, lateral and oblique views expected";
}

}  // namespace
}  // namespace maxillo
