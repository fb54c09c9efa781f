// Issue 28's "real patient with no hands": the real cadaver head CT (../shared/data/cthead-stanford)
// imported without a landmark file gets its landmarks detected and stored, the report shows its
// cephalometry, and planning reads them, refusing flagged ones unless the planner accepts them.
// A set given by hand then takes precedence, and `landmarks detect --store` says how far the
// automatic one lies from it. Skipped where the data is absent.
#include <gtest/gtest.h>

#include <fstream>

#include "support/cadaver_dicom.h"
#include "support/pdf_tools.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

TEST(CadaverNoHands, AReportAndAPlanWithoutALandmarkFile) {
  if (!testing::cadaver_present())
    GTEST_SKIP() << "real data absent: " << testing::cadaver_data() << " (see ../shared/data/README.md)";
  testing::TemporaryFolder folder("maxillo-cadaver-landmarks");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder / "archive");
  const auto wrap = testing::wrap_cadaver_as_dicom(folder / "ct");
  ASSERT_EQ(wrap.exit_code, 0) << wrap.output;
  ASSERT_EQ(run_command(maxillo + " -q import " + quote(folder / "ct")).exit_code, 0);
  ASSERT_EQ(run_command(maxillo + " -q plan create 1 --advance 6").exit_code, 0);

  // Planning on the automatic set: refused while a landmark it reads is flagged, naming it.
  // (On this head the orbitales fail their mirror check; its flat chin is read on the line from
  // nasion, and B and Pog pass theirs.)
  const auto refused = run_command(maxillo + " plan apply 1 --no-face --out " + quote(folder / "plan") + " 2>&1");
  EXPECT_EQ(refused.exit_code, 26) << refused.output;
  EXPECT_NE(refused.output.find("failed their checks"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("OrL (mirror:"), std::string::npos) << refused.output;
  EXPECT_EQ(refused.output.find("B (order"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("--accept-flagged"), std::string::npos) << refused.output;
  // Accepted, the plan passes the jaw separation without first molars (the occlusal plane from
  // the palate). This head's maxillary sinuses open widely into the nasal cavity at 2 mm slices,
  // so no closed air houses a screw: each is read as open air lateral to the nose and walled
  // (planning/maxillary_sinus.h). The distractors' checks then run on real sinuses, and the face
  // is predicted; a check may still fail on this head (a septum in the left sinus meets the
  // screw's clearance ring), which refuses the plan with its reason, not for want of a sinus.
  const auto planned =
      run_command(maxillo + " plan apply 1 --accept-flagged --out " + quote(folder / "plan") + " 2>&1");
  EXPECT_TRUE(planned.exit_code == 0 || planned.exit_code == 63) << planned.output;
  EXPECT_EQ(planned.output.find("needs U6R or L6R"), std::string::npos) << planned.output;
  EXPECT_EQ(planned.output.find("no sinus air"), std::string::npos) << planned.output;
  EXPECT_NE(planned.output.find("sinus: right maxillary sinus open to the nasal cavity"), std::string::npos)
      << planned.output;
  EXPECT_NE(planned.output.find("sinus: left maxillary sinus open to the nasal cavity"), std::string::npos)
      << planned.output;
  EXPECT_NE(planned.output.find("check right screw in sinus     pass"), std::string::npos) << planned.output;
  EXPECT_NE(planned.output.find("check right sinus depth        pass"), std::string::npos) << planned.output;
  EXPECT_NE(planned.output.find("predicted face: largest skin displacement"), std::string::npos) << planned.output;

  ASSERT_EQ(run_command(maxillo + " -q report 1 --out " + quote(folder / "report.pdf")).exit_code, 0);
  const std::string text = testing::pdf_text(folder / "report.pdf");
  EXPECT_NE(text.find("found automatically (maxillo-landmarks 2)"), std::string::npos) << text.substr(0, 3000);
  EXPECT_NE(text.find("SNA"), std::string::npos);
  EXPECT_EQ(text.find("No landmarks are attached"), std::string::npos);
  // The plan (described by its target) and the prediction on the real head.
  EXPECT_NE(text.find("TS-MD distraction: 6 mm advancement"), std::string::npos);
  EXPECT_NE(text.find("maxillary sinus open to the nasal cavity"), std::string::npos);
  EXPECT_NE(text.find("Soft-tissue prediction"), std::string::npos);

  // A set given by hand takes precedence; the automatic one is stored beside it, with distances.
  std::ofstream(folder / "by-hand.csv") << "S,-21.5,-20.5,124\nN,-21.5,-77.5,141\nMe,-21.5,-82.5,24\n";
  ASSERT_EQ(run_command(maxillo + " -q ceph add 1 --time-point pre --date 1989-01-01 " + quote(folder / "by-hand.csv"))
                .exit_code,
            0);
  const auto stored = run_command(maxillo + " landmarks detect 1 --store --only S 2>&1");
  ASSERT_EQ(stored.exit_code, 0) << stored.output;
  EXPECT_NE(stored.output.find("keeps precedence"), std::string::npos) << stored.output;
  EXPECT_NE(stored.output.find("  S  "), std::string::npos) << stored.output;
}

}  // namespace
}  // namespace maxillo
