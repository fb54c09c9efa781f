#include "report/report_template.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/json.h"
#include "core/resources.h"

namespace maxillo::report {
namespace {

Json consultation() { return Json::parse(load_resource("templates/consultation.json")); }

// Expects parse_report_template to reject `bad` with kBadTemplate and a message containing `named`.
void expect_rejected(const Json& bad, const std::string& named) {
  try {
    parse_report_template(bad.dump(), "test.json");
    FAIL() << "expected the template to be rejected for " << named;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kBadTemplate);
    EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("test.json"), std::string::npos) << e.what();
  }
}

TEST(ReportTemplate, ConsultationTemplateLoads) {
  auto t = load_report_template();
  EXPECT_EQ(t.title, "Consultation report");
  EXPECT_EQ(t.footer, "Not a diagnosis: planning aid, verify clinically");
  ASSERT_FALSE(t.sections.empty());
  EXPECT_EQ(t.sections.front().id, "patient");
  EXPECT_DOUBLE_EQ(t.margin_left_mm, 20);
  EXPECT_EQ(t.regular_font, "DejaVuSans.ttf");
}

TEST(ReportTemplate, UnknownKeysAreRejectedWithTheirName) {
  auto root = consultation();
  root["colour"] = "blue";
  expect_rejected(root, "'colour'");

  auto margins = consultation();
  margins["page"]["margins_mm"]["inner"] = 10;
  expect_rejected(margins, "'inner' in page.margins_mm");

  auto section = consultation();
  section["sections"][1]["foot"] = "x";
  expect_rejected(section, "'foot' in sections[1]");
}

TEST(ReportTemplate, UnknownOrRepeatedSectionIdsAreRejected) {
  auto unknown = consultation();
  unknown["sections"].push_back({{"id", "horoscope"}, {"heading", "Stars"}});
  expect_rejected(unknown, "'horoscope'");

  auto repeated = consultation();
  repeated["sections"].push_back({{"id", "summary"}, {"heading", "Again"}});
  expect_rejected(repeated, "'summary' appears twice");
}

TEST(ReportTemplate, MissingMistypedAndOutOfRangeValuesAreRejected) {
  auto missing = consultation();
  missing.erase("footer");
  expect_rejected(missing, "'footer'");

  auto mistyped = consultation();
  mistyped["fonts"]["body_size_pt"] = "ten";
  expect_rejected(mistyped, "'body_size_pt'");

  auto tiny = consultation();
  tiny["fonts"]["body_size_pt"] = 2;
  expect_rejected(tiny, "'body_size_pt'");

  auto letter = consultation();
  letter["page"]["size"] = "Letter";
  expect_rejected(letter, "A4");

  EXPECT_THROW(parse_report_template("{\"title\": ", "test.json"), Error);
}

}  // namespace
}  // namespace maxillo::report
