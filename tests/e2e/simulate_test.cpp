// maxillo simulate end to end on the phantom: sample -> import -> landmarks -> simulate.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/json.h"
#include "core/temporary_folder.h"
#include "mesh/mesh_io.h"
#include "geometry/mesh_measures.h"
#include "support/pdf_tools.h"
#include "support/run_maxillo.h"

namespace maxillo {
namespace {

using testing::run_maxillo;

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Simulate, SixMillimetreAdvancementOfThePhantomGivesAPlausibleFace) {
  TemporaryFolder folder("simulate-e2e");
  const auto dir = folder.path();
  ASSERT_EQ(run_maxillo({"sample", "--out", (dir / "sample").string(), "--spacing", "1.5"}, dir).exit_code, 0);
  const std::string archive = "--archive=" + (dir / "archive").string();
  ASSERT_EQ(run_maxillo({archive, "import", (dir / "sample" / "ct").string()}, dir).exit_code, 0);
  ASSERT_EQ(run_maxillo({archive, "ceph", "add", "MAXILLO-PHANTOM-001", "--time-point", "pre", "--date", "2026-01-02",
                         (dir / "sample" / "landmarks.mrk.json").string()},
                        dir)
                .exit_code,
            0);
  auto run = run_maxillo({archive, "--json", "simulate", "MAXILLO-PHANTOM-001", "--advance", "6", "--model", "fem",
                          "--max-tets", "40000", "--uncertainty", "--out", (dir / "sim").string()},
                         dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto summary = Json::parse(run.out);
  EXPECT_EQ(summary["plan_application"], "applied");  // no `plan apply` has stored this plan's moves
  EXPECT_LE(summary["tetrahedra"].get<int>(), 40000);
  EXPECT_EQ(summary["tet_budget"], 40000);
  EXPECT_EQ(summary["over_tet_budget"], false);
  // Tissue on the moved maxilla slides on it (issue 34): pushed along the bone's normal.
  EXPECT_EQ(summary["bone_contact"], "sliding");
  EXPECT_GT(summary["sliding_nodes"].get<int>(), 50);
  EXPECT_GT(summary["min_dihedral_deg"].get<double>(), 5.0);
  // The face follows a 6 mm advancement by at most about as much, and visibly.
  EXPECT_GT(summary["max_skin_displacement_mm"].get<double>(), 4.0);
  EXPECT_LT(summary["max_skin_displacement_mm"].get<double>(), 7.0);
  EXPECT_EQ(summary["uncertainty"]["runs"].size(), 4u);            // fem 0.46, mtm 0.46, fem 0.45, fem 0.49
  EXPECT_LT(summary["uncertainty"]["p95_mm"].get<double>(), 1.0);  // plausible models agree
  // Issue 34: the profile's response to the maxilla's advancement, read at A (moved rigidly by 6 mm).
  const auto& profile = summary["profile_response"];
  EXPECT_NEAR(profile["advancement_mm"].get<double>(), 6.0, 0.01);
  EXPECT_EQ(profile["reference"], "A");
  EXPECT_EQ(profile["points"].size(), 6u);
  // The cartilaginous nose is a stiffer tissue (casework/softtissue/nasal_cartilage.h).
  EXPECT_GT(summary["nose_tets"].get<int>(), 50);
  EXPECT_NEAR(summary["nose_stiffness"].get<double>(), 67.6, 0.1);
  ASSERT_EQ(summary["boundary_moves"].size(), 3u);  // at the brows, under the chin, in front of the ears
  EXPECT_EQ(summary["boundary_moves"][0]["where"], "at the brows");
  for (const auto& point : profile["points"]) {
    if (point["label"] == "Ls") {
      EXPECT_GT(point["ratio"].get<double>(), 0.5);  // the lip follows its bone
    }
  }
  // The predicted skin: closed like the input, and the VTP carries the displacement per vertex.
  EXPECT_TRUE(is_watertight(read_mesh(dir / "sim" / "predicted-skin.stl")));
  EXPECT_NE(text_of(dir / "sim" / "predicted-skin.vtp").find("Name=\"displacement\""), std::string::npos);
  for (const char* png : {"soft-tissue-before-lateral.png", "soft-tissue-after-lateral.png",
                          "soft-tissue-displacement-frontal.png", "soft-tissue-uncertainty-lateral.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / "sim" / png)) << png;

  // The prediction is kept in the archive: `maxillo report` shows it without predicting again.
  auto report = run_maxillo({archive, "report", "MAXILLO-PHANTOM-001", "--out", (dir / "report.pdf").string()}, dir);
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string text = testing::pdf_text(dir / "report.pdf");
  EXPECT_NE(text.find("Predicted face for the planned bone moves (Le Fort I, maxilla 6.0 mm advancement)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("linear FEM, Poisson ratio 0.46"), std::string::npos) << text;
  EXPECT_NE(text.find("soft tissue, and the cartilaginous nose ("), std::string::npos) << text;
  EXPECT_EQ(testing::count_of(text, "Uncertainty band, "), 2u) << text;  // the two pictures' captions
  EXPECT_NE(text.find("Plausibility: how far the predicted profile moves forward"), std::string::npos) << text;
  EXPECT_NE(text.find("(read at A)"), std::string::npos) << text;
  EXPECT_NE(text.find("The model's edges, where its region cuts the tissue"), std::string::npos) << text;
  EXPECT_NE(text.find("upper lip, labrale superius (Ls)"), std::string::npos) << text;

  // The non-linear model (neo-Hookean) converges on the same face and stays near the linear one.
  auto nonlinear = run_maxillo({archive, "--json", "simulate", "MAXILLO-PHANTOM-001", "--advance", "6", "--model",
                                "nfem", "--out", (dir / "sim-nfem").string()},
                               dir);
  ASSERT_EQ(nonlinear.exit_code, 0) << nonlinear.err;
  const auto nfem = Json::parse(nonlinear.out);
  EXPECT_GT(nfem["max_skin_displacement_mm"].get<double>(), 4.0);
  EXPECT_LT(nfem["max_skin_displacement_mm"].get<double>(), 7.0);

  // Issue 4: `plan apply` writes the transfer model and, with the soft tissue engine in, the face.
  ASSERT_EQ(
      run_maxillo({archive, "plan", "create", "MAXILLO-PHANTOM-001", "--advance", "8", "--widen", "4"}, dir).exit_code,
      0);
  auto apply = run_maxillo({archive, "plan", "apply", "MAXILLO-PHANTOM-001", "--out", (dir / "plan").string()}, dir);
  ASSERT_EQ(apply.exit_code, 0) << apply.err;
  const auto transfer = read_mesh(dir / "plan" / "transfer-model.stl");
  EXPECT_TRUE(is_watertight(transfer));
  EXPECT_GT(signed_volume(transfer), 1000.0);  // mm^3
  for (const char* file :
       {"plan-result.json", "planned-maxilla.stl", "plan-oblique.png", "soft-tissue/simulation.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "plan" / file)) << file;
  // Issue 17: the face of `plan apply` uses the moves it has just stored, not a second application.
  EXPECT_EQ(Json::parse(text_of(dir / "plan" / "soft-tissue" / "simulation.json"))["plan_application"], "stored");
}

// Neither --plan nor --advance: a usage error that says so, before the archive is looked at (the
// archive here does not even exist, which must not be what the command complains about).
TEST(Simulate, WithoutAPlanOrAMoveItSaysWhatIsMissing) {
  TemporaryFolder folder("simulate-usage");
  auto run = run_maxillo(
      {"--archive=" + (folder.path() / "a").string(), "simulate", "1", "--out", (folder.path() / "sim").string()},
      folder.path());
  EXPECT_EQ(run.exit_code, exit_code_for(ErrorCode::kUsage)) << run.err;
  EXPECT_NE(run.err.find("give a plan (--plan PLAN.json) or a Le Fort I advancement (--advance MM)"), std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "a")) << "nothing created";
}

}  // namespace
}  // namespace maxillo
