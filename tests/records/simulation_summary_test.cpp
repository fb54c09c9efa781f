// simulate's summary: written and read back as one record; damage is an error naming the key.
#include "records/simulation_summary.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "support/error_of.h"

namespace maxillo::records {
namespace {

SimulationSummary example_summary() {
  SimulationSummary s;
  s.plan_text = "Le Fort I, maxilla 6.0 mm advancement";
  s.model = "mtm";
  s.poisson_ratio = 0.46;
  s.plan_application_stored = true;
  s.tetrahedra = 41234;
  s.nodes = 9012;
  s.cell_size_mm = 4.25;
  s.meshing_attempts = 3;
  s.tet_budget = 40000;
  s.over_tet_budget = true;
  s.min_dihedral_deg = 11.5;
  s.mean_aspect_ratio = 1.625;
  s.max_aspect_ratio = 6.25;
  s.prescribed_nodes = 300;
  s.fixed_nodes = 1200;
  s.free_nodes = 7512;
  s.iterations = 332;
  s.max_skin_displacement_mm = 10.625;
  s.seconds = {0.5, 6.0, 0.25, 0.125, 0.0625, 0.75};
  s.uncertainty = SimulationSummary::UncertaintyBand{{"mtm nu=0.46", "fem nu=0.46"}, 0.5, 1.25};
  s.soft_landmarks = {{"Sn", 4.5, 0.25, -0.125, 4.5087}, {"Ls", 5.0, 0.5, 0, 5.025}};
  SimulationSummary::ProfileResponse profile;
  profile.advancement_mm = 6;
  profile.reference = "A";
  profile.points = {{"Prn", true, 1.5, 0.25, "0.17", "a 3D series", 0.0, 0.4},
                    {"Li", false, 0, 0, "not measured", "", std::nullopt, std::nullopt}};
  profile.gradient_p999 = 0.5;
  profile.gradient_max = 1.25;
  profile.steepest_near = "Li";
  profile.steepest_near_mm = 2.5;
  s.profile_response = profile;
  s.boundary_moves = {{"below the orbits", 1.375}, {"under the chin", 0.0}};
  s.nose_tets = 812;
  s.nose_stiffness = 30;
  s.model = "fem";
  s.model_fallback = SimulationSummary::ModelFallback{"nfem", "Newton's method did not converge"};
  s.sliding_nodes = 1234;
  s.bone_contact = "sliding";
  s.nose_nodes_uncarried = 3;
  s.squeezed_nodes_freed = 74;
  s.enclosed_voxels_left_out = 64163;
  return s;
}

// The example written as an older format: the fields each later version added taken out.
Json as_version(int version) {
  static const std::map<int, std::vector<const char*>> added{
      {2, {"plan_text", "meshing_attempts", "mean_aspect_ratio", "soft_landmarks"}},
      {3, {"profile_response", "boundary_moves"}},
      {4, {"nose_tets", "nose_stiffness", "model_fallback"}},
      {5, {"sliding_nodes", "bone_contact"}},
      {6, {"nose_nodes_uncarried"}},
      {7, {"squeezed_nodes_freed", "enclosed_voxels_left_out"}}};
  Json json = to_json(example_summary());
  for (const auto& [since, keys] : added)
    if (since > version)
      for (const char* key : keys) json.erase(key);
  json["format_version"] = version;
  return json;
}

TEST(SimulationSummary, RoundTripsThroughItsText) {
  const SimulationSummary written = example_summary();
  const SimulationSummary read = read_simulation_summary(Json::parse(to_json(written).dump(2)), "test");
  EXPECT_EQ(to_json(read), to_json(written));  // every field, compared through the one writer
  EXPECT_EQ(read.tetrahedra, 41234);
  EXPECT_TRUE(read.over_tet_budget);
  EXPECT_TRUE(read.plan_application_stored);
  ASSERT_TRUE(read.uncertainty);
  EXPECT_EQ(read.uncertainty->runs.size(), 2u);
  SimulationSummary without_band = written;
  without_band.uncertainty.reset();
  EXPECT_FALSE(read_simulation_summary(to_json(without_band), "test").uncertainty);
  ASSERT_EQ(read.soft_landmarks.size(), 2u);
  EXPECT_EQ(read.soft_landmarks[1].label, "Ls");
  EXPECT_EQ(read.plan_text, written.plan_text);
  ASSERT_TRUE(read.profile_response);
  ASSERT_EQ(read.profile_response->points.size(), 2u);
  EXPECT_EQ(read.profile_response->points[0].plausible_high, 0.4);
  EXPECT_FALSE(read.profile_response->points[1].plausible_low);  // no band: null, not 0
  SimulationSummary no_advancement = written;
  no_advancement.profile_response.reset();
  EXPECT_TRUE(to_json(no_advancement)["profile_response"].is_null());
  EXPECT_FALSE(read_simulation_summary(to_json(no_advancement), "test").profile_response);
  ASSERT_EQ(read.boundary_moves.size(), 2u);
  EXPECT_EQ(read.boundary_moves[0].where, "below the orbits");
  EXPECT_EQ(read.boundary_moves[0].largest_move_mm, 1.375);
  EXPECT_EQ(read.nose_tets, 812);
  EXPECT_EQ(read.nose_stiffness, 30);
  ASSERT_TRUE(read.model_fallback);
  EXPECT_EQ(read.model_fallback->requested, "nfem");
  SimulationSummary ran_as_asked = written;
  ran_as_asked.model_fallback.reset();
  EXPECT_TRUE(to_json(ran_as_asked)["model_fallback"].is_null());
  EXPECT_FALSE(read_simulation_summary(to_json(ran_as_asked), "test").model_fallback);
  EXPECT_EQ(read.sliding_nodes, 1234);
  EXPECT_EQ(read.bone_contact, "sliding");
  EXPECT_EQ(read.nose_nodes_uncarried, 3);
  EXPECT_EQ(read.squeezed_nodes_freed, 74);
  EXPECT_EQ(read.enclosed_voxels_left_out, 64163);
}

// Version 6 summaries (nothing pinched freed, no tissue shut in by bone left out) still read so.
TEST(SimulationSummary, AVersion6SummaryReadsWithNothingFreedOrLeftOut) {
  const SimulationSummary read = read_simulation_summary(as_version(6), "test");
  EXPECT_EQ(read.squeezed_nodes_freed, 0);
  EXPECT_EQ(read.enclosed_voxels_left_out, 0);
  EXPECT_EQ(read.nose_nodes_uncarried, 3);
}

// Version 5 summaries (the moved bone carried the nose's nodes on it) still read so.
TEST(SimulationSummary, AVersion5SummaryReadsWithTheNoseCarriedByTheBone) {
  const SimulationSummary read = read_simulation_summary(as_version(5), "test");
  EXPECT_EQ(read.nose_nodes_uncarried, 0);
  EXPECT_EQ(read.bone_contact, "sliding");
}

// Version 4 summaries (tissue on moved bone tied to it) still read so.
TEST(SimulationSummary, AVersion4SummaryReadsAsTiedToTheMovedBone) {
  const SimulationSummary read = read_simulation_summary(as_version(4), "test");
  EXPECT_EQ(read.sliding_nodes, 0);
  EXPECT_EQ(read.bone_contact, "tied");
  EXPECT_EQ(read.nose_tets, 812);
}

// Version 3 summaries (every model one homogeneous tissue) still read: no stiffer nose.
TEST(SimulationSummary, AVersion3SummaryReadsAsOneHomogeneousTissue) {
  const SimulationSummary read = read_simulation_summary(as_version(3), "test");
  EXPECT_EQ(read.nose_tets, 0);
  EXPECT_EQ(read.nose_stiffness, 1);
  EXPECT_FALSE(read.model_fallback);
  EXPECT_EQ(read.boundary_moves.size(), 2u);
}

// Version 2 summaries (before the profile's response was added) still read, without it.
TEST(SimulationSummary, AVersion2SummaryReadsWithoutTheProfileResponse) {
  const SimulationSummary read = read_simulation_summary(as_version(2), "test");
  EXPECT_FALSE(read.profile_response);
  EXPECT_EQ(read.soft_landmarks.size(), 2u);
}

// Version 1 summaries (before the report's facts were added) still read, without those facts.
TEST(SimulationSummary, AVersion1SummaryReadsWithoutTheReportFacts) {
  const SimulationSummary read = read_simulation_summary(as_version(1), "test");
  EXPECT_EQ(read.format_version, 1);
  EXPECT_TRUE(read.soft_landmarks.empty());
  EXPECT_EQ(read.tetrahedra, 41234);
}

TEST(SimulationSummary, DamageIsAnErrorNamingTheKey) {
  const Json good = to_json(example_summary());
  auto failure = [&](const std::function<void(Json&)>& damage) {
    return testing::error_after_damage(good, damage,
                                       [](const Json& j) { read_simulation_summary(j, "sim/simulation.json"); });
  };
  EXPECT_EQ(failure([](Json& j) { j.erase("over_tet_budget"); }), "sim/simulation.json: over_tet_budget: missing");
  EXPECT_EQ(failure([](Json& j) { j["model"] = "springs"; }), "sim/simulation.json: model: unknown model \"springs\"");
  EXPECT_EQ(failure([](Json& j) { j["plan_application"] = "maybe"; }),
            "sim/simulation.json: plan_application: must be \"stored\" or \"applied\"");
  EXPECT_EQ(failure([](Json& j) { j["seconds"].erase("solve"); }), "sim/simulation.json: seconds.solve: missing");
  EXPECT_EQ(failure([](Json& j) { j["uncertainty"]["runs"][1] = 3; }),
            "sim/simulation.json: uncertainty.runs[1]: must be a string");
  EXPECT_EQ(failure([](Json& j) { j["tetrahedra"] = -1; }),
            "sim/simulation.json: tetrahedra: must lie in [0, 2147483647]");
  EXPECT_EQ(failure([](Json& j) { j.erase("plan_text"); }), "sim/simulation.json: plan_text: missing");
  EXPECT_EQ(failure([](Json& j) { j["soft_landmarks"][0].erase("up_mm"); }),
            "sim/simulation.json: soft_landmarks[0].up_mm: missing");
  EXPECT_EQ(failure([](Json& j) { j.erase("profile_response"); }), "sim/simulation.json: profile_response: missing");
  EXPECT_EQ(failure([](Json& j) { j["boundary_moves"][1].erase("where"); }),
            "sim/simulation.json: boundary_moves[1].where: missing");
  EXPECT_EQ(failure([](Json& j) { j["profile_response"]["points"][0]["plausible_high"] = "high"; }),
            "sim/simulation.json: profile_response.points[0].plausible_high: must be a number");
  EXPECT_EQ(failure([](Json& j) { j.erase("nose_tets"); }), "sim/simulation.json: nose_tets: missing");
  EXPECT_EQ(failure([](Json& j) { j.erase("model_fallback"); }), "sim/simulation.json: model_fallback: missing");
  EXPECT_EQ(failure([](Json& j) { j["model_fallback"]["requested"] = "springs"; }),
            "sim/simulation.json: model_fallback.requested: unknown model \"springs\"");
  EXPECT_NE(failure([](Json& j) { j["nose_stiffness"] = 0.5; }).find("sim/simulation.json: nose_stiffness: must"),
            std::string::npos);
  EXPECT_EQ(failure([](Json& j) { j["bone_contact"] = "glued"; }),
            "sim/simulation.json: bone_contact: unknown contact \"glued\"");
  EXPECT_EQ(failure([](Json& j) { j.erase("sliding_nodes"); }), "sim/simulation.json: sliding_nodes: missing");
  EXPECT_EQ(failure([](Json& j) { j.erase("nose_nodes_uncarried"); }),
            "sim/simulation.json: nose_nodes_uncarried: missing");
  EXPECT_EQ(failure([](Json& j) { j.erase("squeezed_nodes_freed"); }),
            "sim/simulation.json: squeezed_nodes_freed: missing");
  EXPECT_EQ(failure([](Json& j) { j["format_version"] = 8; }),
            "sim/simulation.json: format_version: is 8, newer than this program reads (7): update maxillo");
}

}  // namespace
}  // namespace maxillo::records
