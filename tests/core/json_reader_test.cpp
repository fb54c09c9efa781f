// JsonReader: required fields fail loudly with the key path; optional ones keep their default.
#include "core/json_reader.h"

#include <gtest/gtest.h>

#include <string>
#include "support/error_of.h"

namespace maxillo {
namespace {

const Json kRecord = Json::parse(R"({"format_version": 2, "feasible": true, "name": "plan",
  "rows": [{"value_mm": 1.5, "point": [1, 2, 3]}, {"value_mm": "2"}], "nested": {"count": 7},
  "notes": ["a", "b"], "mixed": {"notes": ["a", 3]}})");

TEST(JsonReader, ReadsRequiredFields) {
  JsonReader r(kRecord, "", "artefact 3", ErrorCode::kArchiveCorrupt);
  EXPECT_EQ(r.required_integer("format_version", 1, 5), 2);
  EXPECT_TRUE(r.required_bool("feasible"));
  EXPECT_EQ(r.required_text("name"), "plan");
  const Json& rows = r.required_array("rows");
  JsonReader first = r.element(rows, "rows", 0);
  EXPECT_EQ(first.required_number("value_mm", 0, 10), 1.5);
  EXPECT_EQ(first.required_point("point"), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(r.object("nested").required_integer("count"), 7);
  EXPECT_EQ(r.required_texts("notes"), (std::vector<std::string>{"a", "b"}));
  r.at("mixed");
  r.refuse_unknown_keys();  // every key was asked for
}

TEST(JsonReader, OptionalFieldsKeepTheirDefaultOnlyWhenAbsent) {
  JsonReader r(kRecord, "", "artefact 3", ErrorCode::kArchiveCorrupt);
  double absent = 4.5;
  r.number("absent_mm", absent, 0, 10);
  EXPECT_EQ(absent, 4.5);
  int version = 0;
  r.integer("format_version", version, 1, 5);
  EXPECT_EQ(version, 2);
  std::string name = "x";
  r.text("name", name);
  EXPECT_EQ(name, "plan");
}

TEST(JsonReader, FailuresNameTheSourceAndTheKeyPath) {
  auto reader = [] { return JsonReader(kRecord, "", "artefact 3", ErrorCode::kArchiveCorrupt, "validation"); };
  EXPECT_EQ(testing::error_of([&] { reader().required_bool("missing"); }), "artefact 3: missing: missing");
  EXPECT_EQ(testing::error_of([&] { reader().required_bool("name"); }), "artefact 3: name: must be true or false");
  EXPECT_EQ(testing::error_of([&] { reader().required_integer("format_version", 3, 5); }),
            "artefact 3: format_version: must lie in [3, 5]");
  EXPECT_EQ(testing::error_of([&] {
              JsonReader r = reader();
              r.element(r.required_array("rows"), "rows", 1).required_number("value_mm");
            }),
            "artefact 3: rows[1].value_mm: must be a number");
  EXPECT_EQ(testing::error_of([&] { reader().object("mixed").required_texts("notes"); }),
            "artefact 3: mixed.notes[1]: must be a string");
  EXPECT_EQ(testing::error_of([&] { reader().required_texts("name"); }), "artefact 3: name: must be an array");
  EXPECT_EQ(testing::error_of([&] { reader().object("nested").required_text("count"); }),
            "artefact 3: nested.count: must be a string");
  EXPECT_EQ(testing::error_of([&] {
              JsonReader r = reader();
              r.required_bool("feasible");
              r.refuse_unknown_keys();
            }),
            "artefact 3: format_version: unknown key");
  const Json array = Json::array();
  EXPECT_EQ(testing::error_of([&] { JsonReader(array, "", "artefact 3", ErrorCode::kArchiveCorrupt, "validation"); }),
            "artefact 3: validation: must be an object");
}

}  // namespace
}  // namespace maxillo
