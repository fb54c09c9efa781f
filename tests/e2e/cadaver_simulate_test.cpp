// The soft tissue prediction on the real cadaver head CT (../shared/data/cthead-stanford): a
// 6 mm Le Fort I advancement gives a face model within the budget, joined to the moved maxilla,
// moving the skin by about the advancement; with landmarks found on import, a profile that follows
// published series on two meshes. Skipped where the data is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "core/json.h"
#include "support/cadaver_dicom.h"
#include "support/pdf_tools.h"
#include "support/run_command.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {
using testing::quote;
using testing::run_command;

// Landmarks placed by hand on mid-sagittal and axial slices of the scan as wrapped by
// scripts/cthead-to-dicom (LPS mm; the head's midline is at x = -21.5). Within a few mm: enough
// for the frame, the region's cut planes, the occlusal plane and the Le Fort I cut.
constexpr const char* kLandmarks = R"(label,x,y,z
S,-21.5,-20.5,124
N,-21.5,-77.5,141
ANS,-21.5,-94.5,94
PNS,-21.5,-39.5,97
U1,-21.5,-100.5,69
L1,-21.5,-92.5,65
B,-21.5,-91.5,51
Pog,-21.5,-90.5,37
Me,-21.5,-82.5,24
U6R,-46.5,-75,70
U6L,3.5,-75,70
L6R,-46.5,-75,66
L6L,3.5,-75,66
OrR,-54.5,-70,116
OrL,11.5,-70,116
PoR,-83.5,20,110
PoL,40.5,20,110
)";

TEST(CadaverSimulate, LeFortAdvancementOnTheRealHead) {
  if (!testing::cadaver_present())
    GTEST_SKIP() << "real data absent: " << testing::cadaver_data() << " (see ../shared/data/README.md)";
  testing::TemporaryFolder folder("maxillo-cadaver-simulate");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder / "archive");
  const auto wrap = testing::wrap_cadaver_as_dicom(folder / "ct");
  ASSERT_EQ(wrap.exit_code, 0) << wrap.output;
  ASSERT_EQ(run_command(maxillo + " import " + quote(folder / "ct") + " 2>&1").exit_code, 0);
  std::ofstream(folder / "landmarks.csv") << kLandmarks;
  auto add = run_command(maxillo + " ceph add CTHEAD-UNC --time-point pre --date 1989-01-01 " +
                         quote(folder / "landmarks.csv") + " 2>&1");
  ASSERT_EQ(add.exit_code, 0) << add.output;

  auto run =
      run_command(maxillo + " --json simulate CTHEAD-UNC --advance 6 --out " + quote(folder / "sim") + " 2>/dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary = Json::parse(run.output);
  EXPECT_LE(summary["tetrahedra"].get<int>(), 100000);
  EXPECT_GT(summary["min_dihedral_deg"].get<double>(), 3.0);
  EXPECT_EQ(summary["bone_contact"], "sliding");  // tissue slides on the moved maxilla (issue 34)
  EXPECT_GT(summary["sliding_nodes"].get<int>(), 50);
  const double largest = summary["max_skin_displacement_mm"].get<double>();
  EXPECT_GT(largest, 4.0);
  EXPECT_LT(largest, 9.0);
  EXPECT_TRUE(std::filesystem::exists(folder / "sim" / "soft-tissue-displacement-lateral.png"));
  EXPECT_TRUE(summary["model_fallback"].is_null());  // the mass tensor model ran, as asked

  // The non-linear FEM converges on this head (issue 34: adaptive load steps, and Newton steps that
  // go down the energy where the compressed tissue's tangent is indefinite): it runs as asked, and
  // its face lies within a millimetre of the mass tensor model's at the largest move.
  auto nonlinear = run_command(maxillo + " --json simulate CTHEAD-UNC --advance 6 --model nfem --out " +
                               quote(folder / "sim-nfem") + " 2>/dev/null");
  ASSERT_EQ(nonlinear.exit_code, 0) << nonlinear.output;
  const auto ran = Json::parse(nonlinear.output);
  EXPECT_EQ(ran["model"], "nfem");
  EXPECT_TRUE(ran["model_fallback"].is_null()) << ran["model_fallback"].dump();
  EXPECT_NEAR(ran["max_skin_displacement_mm"].get<double>(), largest, 1.0);
  ASSERT_EQ(run_command(maxillo + " -q report CTHEAD-UNC --out " + quote(folder / "report.pdf")).exit_code, 0);
  const std::string text = testing::pdf_text(folder / "report.pdf");
  EXPECT_EQ(text.find("did not converge on this face"), std::string::npos) << text.substr(0, 4000);
}

// The profile point `label`'s forward move over the advancement in a simulate summary.
double profile_ratio(const Json& summary, const std::string& label) {
  for (const auto& point : summary["profile_response"]["points"])
    if (point["label"] == label && point["present"].get<bool>()) return point["ratio"].get<double>();
  ADD_FAILURE() << "no profile point " << label;
  return NAN;
}

// With no hands (landmarks found on import), the face predicted for a 6 mm advancement moves as
// published series measure (issue 34: nose tip <= 0.40, dorsum <= 0.25, subnasale 0.40-0.95 of
// the advancement), and it is the model's answer, not the mesh's: a finer mesh moves the profile
// by under 0.04 of the advancement. While the maxilla carried the stiff nose's few nodes on it,
// the tip read 0.31 at 4 mm cells and 0.36 at 3 mm, subnasale 0.85 and 0.92.
TEST(CadaverSimulate, TheProfileFollowsPublishedSeriesAndNotTheMesh) {
  if (!testing::cadaver_present())
    GTEST_SKIP() << "real data absent: " << testing::cadaver_data() << " (see ../shared/data/README.md)";
  testing::TemporaryFolder folder("maxillo-cadaver-profile");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder / "archive");
  const auto wrap = testing::wrap_cadaver_as_dicom(folder / "ct");
  ASSERT_EQ(wrap.exit_code, 0) << wrap.output;
  ASSERT_EQ(run_command(maxillo + " -q import " + quote(folder / "ct")).exit_code, 0);
  auto simulate = [&](const std::string& meshing, const std::string& out) {
    auto run = run_command(maxillo + " --json simulate 1 --advance 6 --accept-flagged " + meshing + " --out " +
                           quote(folder / out) + " 2>/dev/null");
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return run.exit_code == 0 ? Json::parse(run.output) : Json::object();
  };
  const Json coarse = simulate("", "sim-4mm"), fine = simulate("--cell-mm 3 --max-tets 200000", "sim-3mm");
  ASSERT_TRUE(coarse.contains("profile_response") && fine.contains("profile_response"));
  EXPECT_GT(coarse["nose_tets"].get<int>(), 0);
  EXPECT_GT(coarse["nose_nodes_uncarried"].get<int>(), 0);
  EXPECT_LT(fine["cell_size_mm"].get<double>(), coarse["cell_size_mm"].get<double>() - 0.5);  // really finer
  EXPECT_LE(profile_ratio(coarse, "Prn"), 0.40);
  EXPECT_LE(profile_ratio(coarse, "dorsum"), 0.25);
  EXPECT_GE(profile_ratio(coarse, "Sn"), 0.40);
  EXPECT_LE(profile_ratio(coarse, "Sn"), 0.95);
  for (const char* label : {"Prn", "dorsum", "Sn", "Ls"})
    EXPECT_NEAR(profile_ratio(coarse, label), profile_ratio(fine, label), 0.04) << label;
}

}  // namespace
}  // namespace maxillo
