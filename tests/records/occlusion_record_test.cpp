// The occlusion result (occlusion.json): written and read back as one record; damage is an error
// naming the key; a result written before "format_version" existed reads as version 1.
#include "records/occlusion_record.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"
#include "support/error_of.h"

namespace maxillo::records {
namespace {

OcclusionRecord example_occlusion() {
  OcclusionRecord r;
  r.upper_file = "upper.stl";
  r.lower_file = "lower.stl";
  r.frame = "lower file coordinates (mm)";
  r.upper_transform = Eigen::AngleAxisd(0.125, Eigen::Vector3d::UnitX()) * Eigen::Translation3d(0.5, -1.0, 2.25);
  r.start_transform.pretranslate(Eigen::Vector3d(0, 0, 1.5));
  r.upper_centroid = Eigen::Vector3d(12.5, -3.25, 40.0);
  r.converged = true;
  r.iterations = 42;
  r.residual_spring_mm = {0.25, 0.5, 0.125, 0.75};
  r.penetration_mm = 0.0625;
  r.allowed_penetration_mm = 0.125;
  r.intersecting_triangle_pairs = 0;
  r.contact_threshold_mm = 1.0;
  r.upper = {12, 3.5, {{0, 400, 7, 1.5, 0.25}, {1, 380, 5, 2.0, -0.0625}}};
  r.lower = {9, 3.0, {{0, 410, 9, 3.0, 0.25}}};
  r.upper_repair = {2, 1, 3, 0, {"shell 1 turned outward"}};
  r.lower_repair = {1, 0, 0, 0, {}};
  r.splint =
      OcclusionRecord::Splint{"splint.stl", 2, 1, 0.1, 0.25, 2.125, 96, 1234.5, 20480, true, 1, 0.125, 0.25, 0, 0, 3.5};
  r.files = {"occlusionogram.png", "upper_distances.csv", "lower_distances.csv", "splint.stl"};
  return r;
}

TEST(OcclusionRecord, RoundTripsThroughItsText) {
  const OcclusionRecord written = example_occlusion();
  const OcclusionRecord read = read_occlusion_record(Json::parse(to_json(written).dump(2)), "test");
  EXPECT_EQ(to_json(read), to_json(written));  // every field, compared through the one writer
  EXPECT_TRUE(read.upper_transform.isApprox(written.upper_transform, 1e-15));
  EXPECT_EQ(read.upper.teeth.size(), 2u);
  EXPECT_DOUBLE_EQ(read.upper.teeth[1].min_distance_mm, -0.0625);
  ASSERT_TRUE(read.upper_centroid);
  EXPECT_EQ(*read.upper_centroid, Eigen::Vector3d(12.5, -3.25, 40.0));
  ASSERT_TRUE(read.splint);
  EXPECT_EQ(read.splint->triangles, 20480);

  OcclusionRecord failed_splint = written;  // the splint asked for but not made: its reason
  failed_splint.splint.reset();
  failed_splint.splint_error = "the arches do not overlap";
  const OcclusionRecord read_failed = read_occlusion_record(to_json(failed_splint), "test");
  EXPECT_FALSE(read_failed.splint);
  EXPECT_EQ(read_failed.splint_error, "the arches do not overlap");

  OcclusionRecord no_splint = written;  // none asked for: null
  no_splint.splint.reset();
  EXPECT_TRUE(to_json(no_splint)["splint"].is_null());
  EXPECT_FALSE(read_occlusion_record(to_json(no_splint), "test").splint);
}

// Results written before "format_version" existed, and version 1 ones, read without the
// arch's centroid (version 2 added it).
TEST(OcclusionRecord, OlderResultsReadAsVersion1WithoutTheCentroid) {
  Json old = to_json(example_occlusion());
  old.erase("format_version");
  old.erase("upper_centroid");
  const OcclusionRecord read = read_occlusion_record(old, "test");
  EXPECT_EQ(read.format_version, 1);
  EXPECT_FALSE(read.upper_centroid);
}

TEST(OcclusionRecord, DamageIsAnErrorNamingTheKey) {
  const Json good = to_json(example_occlusion());
  auto failure = [&](const std::function<void(Json&)>& damage) {
    return testing::error_after_damage(good, damage,
                                       [](const Json& j) { read_occlusion_record(j, "artefact 7 (occlusion)"); });
  };
  const std::string source = "artefact 7 (occlusion): ";
  EXPECT_EQ(failure([](Json& j) { j.erase("upper_transform"); }), source + "upper_transform: missing");
  EXPECT_EQ(failure([](Json& j) { j["status"] = "done"; }),
            source + "status: must be \"converged\" or \"iteration_limit\"");
  EXPECT_EQ(failure([](Json& j) { j["residual_spring_mm"][2] = "far"; }),
            source + "residual_spring_mm[2]: must be a number");
  EXPECT_EQ(failure([](Json& j) { j["upper"]["teeth"][1].erase("contact_area_mm2"); }),
            source + "upper.teeth[1].contact_area_mm2: missing");
  EXPECT_EQ(failure([](Json& j) { j["repairs"]["lower"]["notes"] = "none"; }),
            source + "repairs.lower.notes: must be an array");
  EXPECT_EQ(failure([](Json& j) { j["splint"].erase("watertight"); }), source + "splint.watertight: missing");
  EXPECT_EQ(failure([](Json& j) { j["splint"] = 3; }), source + "splint: must be an object or null");
  EXPECT_EQ(failure([](Json& j) { j["iterations"] = -1; }), source + "iterations: must lie in [0, 2147483647]");
  EXPECT_EQ(failure([](Json& j) { j.erase("upper_centroid"); }), source + "upper_centroid: missing");
  EXPECT_EQ(failure([](Json& j) { j["format_version"] = 3; }),
            source + "format_version: is 3, newer than this program reads (2): update maxillo");
}

}  // namespace
}  // namespace maxillo::records
