// A patient name outside ASCII travels the whole way: DICOM (ISO_IR 192) -> archive (SQLite)
// -> report (libharu, embedded TrueType) -> text extracted by pdftotext.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>

#include "support/pdf_tools.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

// A 128 mm cube of air holding a soft-tissue ball (r 45 mm) around a bone ball (r 25 mm),
// written as MetaImage (header + raw little-endian int16 HU) for `maxillo convert`.
void write_ball_volume(const std::filesystem::path& header) {
  constexpr int n = 64;
  constexpr double spacing = 2.0, centre = (n - 1) * spacing / 2;
  std::vector<int16_t> hu(size_t(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double dx = i * spacing - centre, dy = j * spacing - centre, dz = k * spacing - centre;
        double r = std::sqrt(dx * dx + dy * dy + dz * dz);
        hu[size_t(i) + n * (size_t(j) + n * size_t(k))] = r < 25 ? 1000 : r < 45 ? 40 : -1000;
      }
  std::ofstream(header.parent_path() / "ball.raw", std::ios::binary)
      .write(reinterpret_cast<const char*>(hu.data()), std::streamsize(hu.size() * sizeof(int16_t)));
  std::ofstream(header) << "ObjectType = Image\nNDims = 3\nDimSize = 64 64 64\nElementSpacing = 2 2 2\n"
                           "ElementType = MET_SHORT\nElementByteOrderMSB = False\nElementDataFile = ball.raw\n";
}

TEST(UnicodeReport, PatientNameSurvivesDicomArchiveAndPdf) {
  testing::TemporaryFolder folder("maxillo-unicode");
  write_ball_volume(folder / "ball.mhd");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder / "archive");
  auto convert = run_command(std::string(MAXILLO_BINARY) + " convert " + quote(folder / "ball.mhd") + " --out " +
                             quote(folder / "ct") + " --patient-name 'Müller-Łukasz^Zoë' --patient-id UTF8-001 2>&1");
  ASSERT_EQ(convert.exit_code, 0) << convert.output;
  auto import = run_command(maxillo + " import " + quote(folder / "ct") + " 2>&1");
  ASSERT_EQ(import.exit_code, 0) << import.output;

  auto listed = run_command(maxillo + " --json list patients 2>/dev/null");
  EXPECT_NE(listed.output.find("Müller-Łukasz^Zoë"), std::string::npos) << listed.output;

  auto report = run_command(maxillo + " report UTF8-001 --out " + quote(folder / "report.pdf") + " 2>&1");
  ASSERT_EQ(report.exit_code, 0) << report.output;
  auto text = testing::pdf_text(folder / "report.pdf");
  EXPECT_NE(text.find("Müller-Łukasz, Zoë"), std::string::npos) << text.substr(0, 400);
  EXPECT_EQ(run_command("qpdf --check " + quote(folder / "report.pdf") + " >/dev/null 2>&1").exit_code, 0);
}

}  // namespace
}  // namespace maxillo
